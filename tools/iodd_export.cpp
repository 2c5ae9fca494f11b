// IODD-like export (issue 13): everything comes from the tables in
// device_logic (parameter table, process-data layout, event list), so the
// document cannot drift from what the device answers.
#include "tools/iodd_export.hpp"

#include <map>
#include <sstream>
#include <string_view>
#include <vector>

#include <fmt/format.h>

#include "device_logic/faults.hpp"
#include "device_logic/parameter_table.hpp"
#include "device_logic/process_data.hpp"
#include "io/html_page.hpp"

namespace sreh::tools {
namespace {

// IODD text is ASCII: anything else becomes a character reference.
std::string xml_escape(std::string_view s) { return io::html_escape(s, io::NonAscii::AsReference); }

std::string iodd_hex_octets(std::string_view bytes) {
  std::string out;
  for (unsigned char c : bytes) out += fmt::format("{:02X}", c);
  return out;
}

std::string_view access_rights(Access a) {
  switch (a) {
    case Access::R: return "ro";
    case Access::W: return "wo";
    case Access::RW: return "rw";
  }
  return "ro";
}

// The texts of the document, referenced by id (IODD's ExternalTextCollection).
class Texts {
 public:
  std::string add(const std::string& id, std::string_view value) {
    texts_.emplace_back(id, std::string(value));
    return id;
  }
  void write(std::ostream& os) const {
    os << "  <ExternalTextCollection>\n    <PrimaryLanguage xml:lang=\"en\">\n";
    for (const auto& [id, value] : texts_)
      os << fmt::format("      <Text id=\"{}\" value=\"{}\"/>\n", id, xml_escape(value));
    os << "    </PrimaryLanguage>\n  </ExternalTextCollection>\n";
  }

 private:
  std::vector<std::pair<std::string, std::string>> texts_;
};

// <SimpleDatatype> / <Datatype> of one table row (IODD type names).
std::string datatype(const ParameterEntry& row, std::string_view element) {
  switch (row.type) {
    case ParamType::UInt8:
    case ParamType::UInt16:
    case ParamType::UInt32:
    case ParamType::Int32:
      return fmt::format(
          "<{} xsi:type=\"{}\" bitLength=\"{}\"><ValueRange lowerValue=\"{}\" upperValue=\"{}\"/></{}>", element,
          row.type == ParamType::Int32 ? "IntegerT" : "UIntegerT", wire_size(row.type) * 8, row.min, row.max,
          element);
    case ParamType::String:
      return fmt::format("<{} xsi:type=\"StringT\" fixedLength=\"{}\" encoding=\"UTF-8\"/>", element,
                         row.max_length);
    case ParamType::OctetString:
    case ParamType::Record: // 40/41: opaque images of the process data
      return fmt::format("<{} xsi:type=\"OctetStringT\" fixedLength=\"{}\"/>", element, row.max_length);
  }
  return {};
}

std::string default_value(const ParameterEntry& row) {
  if (row.access == Access::W) return {}; // commands have no default
  if (is_numeric(row.type)) return std::to_string(row.default_value);
  if (row.default_text.empty()) return {}; // computed by the device
  return row.type == ParamType::String ? xml_escape(row.default_text) : iodd_hex_octets(row.default_text);
}

// Our extension attributes (the schema allows them): the raw unit, the
// display unit and scale, and the manual section.
std::string row_attributes(const ParameterEntry& row) {
  std::string a = fmt::format(" section=\"{}\"", xml_escape(row.section));
  if (!row.raw_unit.empty()) a += fmt::format(" rawUnit=\"{}\"", xml_escape(row.raw_unit));
  if (!row.display_unit.empty())
    a += fmt::format(" unit=\"{}\" scale=\"{}\"", xml_escape(row.display_unit), row.display_scale);
  return a;
}

void write_variables(std::ostream& os, Texts& texts) {
  os << "      <VariableCollection>\n";
  std::map<uint16_t, std::vector<const ParameterEntry*>> records;
  std::vector<uint16_t> order;
  for (const auto& row : parameter_table()) {
    if (row.record_name.empty()) {
      const std::string id = fmt::format("V_{}", row.index);
      const std::string def = default_value(row);
      os << fmt::format("        <Variable id=\"{}\" index=\"{}\" accessRights=\"{}\"{}{}>\n", id, row.index,
                        access_rights(row.access), def.empty() ? "" : fmt::format(" defaultValue=\"{}\"", def),
                        row_attributes(row));
      os << "          " << datatype(row, "Datatype") << "\n";
      os << fmt::format("          <Name textId=\"{}\"/>\n", texts.add("TN_" + id, row.name));
      if (!row.notes.empty())
        os << fmt::format("          <Description textId=\"{}\"/>\n", texts.add("TD_" + id, row.notes));
      os << "        </Variable>\n";
      continue;
    }
    if (!records.contains(row.index)) order.push_back(row.index);
    records[row.index].push_back(&row);
  }
  // Records after the plain variables, each once, in index order.
  for (const uint16_t index : order) {
    const auto& members = records[index];
    const std::string id = fmt::format("V_{}", index);
    const ParameterEntry& first = *members.front();
    std::size_t bits = 0;
    for (const auto* m : members) bits += wire_size(m->type) * 8;
    os << fmt::format("        <Variable id=\"{}\" index=\"{}\" accessRights=\"{}\" section=\"{}\">\n", id, index,
                      access_rights(first.access), xml_escape(first.section));
    os << fmt::format("          <Datatype xsi:type=\"RecordT\" bitLength=\"{}\" subindexAccessSupported=\"true\">\n",
                      bits);
    // Subindex 1 is sent first (most significant), as ISDU concatenates them.
    std::size_t offset = bits;
    for (const auto* m : members) {
      offset -= wire_size(m->type) * 8;
      const std::string item_id = fmt::format("{}_{}", id, m->subindex);
      os << fmt::format("            <RecordItem subindex=\"{}\" bitOffset=\"{}\" accessRights=\"{}\"{}>\n",
                        m->subindex, offset, access_rights(m->access), row_attributes(*m));
      os << "              " << datatype(*m, "SimpleDatatype") << "\n";
      os << fmt::format("              <Name textId=\"{}\"/>\n", texts.add("TN_" + item_id, m->name));
      if (!m->notes.empty())
        os << fmt::format("              <Description textId=\"{}\"/>\n", texts.add("TD_" + item_id, m->notes));
      os << "            </RecordItem>\n";
    }
    os << "          </Datatype>\n";
    for (const auto* m : members) {
      const std::string def = default_value(*m);
      if (!def.empty())
        os << fmt::format("          <RecordItemInfo subindex=\"{}\" defaultValue=\"{}\"/>\n", m->subindex, def);
    }
    os << fmt::format("          <Name textId=\"{}\"/>\n", texts.add("TN_" + id, first.record_name));
    os << "        </Variable>\n";
  }
  os << "      </VariableCollection>\n";
}

std::string pd_datatype(PdFieldType type) {
  switch (type) {
    case PdFieldType::Int32: return "<SimpleDatatype xsi:type=\"IntegerT\" bitLength=\"32\"/>";
    case PdFieldType::UInt8: return "<SimpleDatatype xsi:type=\"UIntegerT\" bitLength=\"8\"/>";
    case PdFieldType::Bool: return "<SimpleDatatype xsi:type=\"BooleanT\"/>";
  }
  return {};
}

template <class Row, std::size_t N>
void write_pd(std::ostream& os, Texts& texts, std::string_view element, std::string_view id, std::size_t bytes,
              const std::array<Row, N>& fields) {
  os << fmt::format("          <{} id=\"{}\" bitLength=\"{}\">\n", element, id, bytes * 8);
  os << fmt::format("            <Datatype xsi:type=\"RecordT\" bitLength=\"{}\" subindexAccessSupported=\"false\">\n",
                    bytes * 8);
  for (std::size_t i = 0; i < N; ++i) {
    const PdField& f = fields[i];
    const std::string item_id = fmt::format("{}_{}", id, f.name);
    os << fmt::format("              <RecordItem subindex=\"{}\" bitOffset=\"{}\" section=\"{}\">\n", i + 1,
                      f.bit_offset, f.section);
    os << "                " << pd_datatype(f.type) << "\n";
    os << fmt::format("                <Name textId=\"{}\"/>\n", texts.add("TN_" + item_id, f.manual_name));
    os << "              </RecordItem>\n";
  }
  os << "            </Datatype>\n";
  os << fmt::format("            <Name textId=\"{}\"/>\n", texts.add(fmt::format("TN_{}", id), element));
  os << fmt::format("          </{}>\n", element);
}

void write_events(std::ostream& os, Texts& texts) {
  os << "      <EventCollection>\n";
  auto event = [&](const EventDefinition& e) {
    os << fmt::format("        <Event code=\"{}\" type=\"{}\" section=\"{}\">\n", e.code,
                      e.type == EventType::Error ? "Error" : "Warning", xml_escape(e.section));
    os << fmt::format("          <Name textId=\"{}\"/>\n", texts.add(fmt::format("TN_E_{:04X}", e.code), e.name));
    os << "        </Event>\n";
  };
  for (const auto& e : kErrorEvents) event(e);
  for (const auto& e : kWarningEvents) event(e);
  os << "      </EventCollection>\n";
}

std::string_view default_text_of(uint16_t index) {
  const ParameterEntry* row = find_parameter(index, 0);
  return row == nullptr ? std::string_view{} : row->default_text;
}

} // namespace

std::string iodd_document(const std::string& generator_version) {
  Texts texts;
  std::ostringstream os;
  os << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n";
  os << "<!-- Generated by sreh-twin (params export, iodd option) from device_logic's tables. IODD vocabulary;\n"
        "     schema: docs/iodd/sreh-iodd.xsd. Vendor and device ID are not in the manual (A-IODD-1). -->\n";
  os << "<IODevice xmlns:xsi=\"http://www.w3.org/2001/XMLSchema-instance\">\n";
  os << fmt::format("  <DocumentInfo version=\"{}\" copyright=\"generated by sreh-twin\"/>\n",
                    xml_escape(generator_version));
  os << "  <ProfileHeader>\n    <ProfileIdentification>IO Device Profile</ProfileIdentification>\n"
        "    <ProfileRevision>1.1</ProfileRevision>\n  </ProfileHeader>\n";
  os << "  <ProfileBody>\n";
  os << fmt::format("    <DeviceIdentity vendorId=\"0\" deviceId=\"0\" vendorName=\"{}\">\n",
                    xml_escape(default_text_of(16)));
  os << fmt::format("      <VendorText textId=\"{}\"/>\n", texts.add("TI_VendorText", default_text_of(17)));
  os << fmt::format("      <VendorUrl textId=\"{}\"/>\n", texts.add("TI_VendorUrl", default_text_of(17)));
  os << fmt::format("      <DeviceName textId=\"{}\"/>\n", texts.add("TI_DeviceName", default_text_of(18)));
  os << fmt::format("      <DeviceFamily textId=\"{}\"/>\n", texts.add("TI_DeviceFamily", default_text_of(19)));
  os << "    </DeviceIdentity>\n";
  os << "    <DeviceFunction>\n";
  // Common Profile, Locator, Firmware Update (manual 1; index 13).
  os << "      <Features blockParameter=\"true\" dataStorage=\"true\" profileCharacteristic=\"16384 33025 49\"/>\n";
  write_variables(os, texts);
  os << "      <ProcessDataCollection>\n        <ProcessData id=\"P_ProcessData\">\n";
  write_pd(os, texts, "ProcessDataIn", "PDI", kPdInBytes, kPdInFields);
  write_pd(os, texts, "ProcessDataOut", "PDO", kPdOutBytes, kPdOutFields);
  os << "        </ProcessData>\n      </ProcessDataCollection>\n";
  write_events(os, texts);
  os << "    </DeviceFunction>\n  </ProfileBody>\n";
  // COM3, 2 ms minimum cycle time (manual 1), in microseconds as IODD counts it.
  os << "  <CommNetworkProfile iolinkRevision=\"V1.1\">\n    <TransportLayers>\n"
        "      <PhysicalLayer bitrate=\"COM3\" minCycleTime=\"2000\" sioSupported=\"false\"/>\n"
        "    </TransportLayers>\n  </CommNetworkProfile>\n";
  texts.write(os);
  os << "</IODevice>\n";
  return os.str();
}

} // namespace sreh::tools
