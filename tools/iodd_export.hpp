// An IODD-like XML description of the device, generated from the parameter
// table, the process-data layout and the event list (issue 13): IODD's own
// vocabulary (IODevice, DeviceIdentity, VariableCollection, Variable index,
// RecordItem subindex, ProcessDataIn/Out, EventCollection), checked against
// the project's schema docs/iodd/sreh-iodd.xsd.
#pragma once
#include <string>

namespace sreh::tools {

// The whole document. Deterministic: the same build writes the same bytes.
std::string iodd_document(const std::string& generator_version);

} // namespace sreh::tools
