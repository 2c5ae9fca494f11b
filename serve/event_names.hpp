// What a device event of index 37 means (issue 39): the fields serve adds to
// every `device_event` (HTTP event stream, MQTT) from the one table of codes
// (device_logic/faults.hpp), so that a client shows a name and a remedy, not
// only 0x8CA3.
#pragma once
#include <cstdint>

#include <nlohmann/json.hpp>

#include "twin/twin.hpp"

namespace sreh::serve {

// {"name", "index", "cause_code", "remedy", "label"}: the cause the module
// holds now in 114.x / 115.x (read over ISDU; while the event appears), or,
// when that is gone or the bit has several causes, the bit's name and
// cause_code / remedy null. label: "position tracking error (114.5)".
// An event the table does not know: name "event 0xNNNN", the rest null.
nlohmann::ordered_json describe_device_event(Twin& twin, uint16_t code);

} // namespace sreh::serve
