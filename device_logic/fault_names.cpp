#include "device_logic/fault_names.hpp"

#include <cctype>

namespace sreh {
namespace {

std::string byte_names(EventType type, uint8_t byte) {
  std::string out;
  for (int bit = 0; bit < 8; ++bit) {
    if (!(byte & (1u << bit))) continue;
    if (!out.empty()) out += "; ";
    const std::string_view name = bit_name(type, static_cast<uint8_t>(bit));
    if (name.empty()) {
      out += "unused bit " + std::to_string(bit);
      continue;
    }
    out += mid_sentence(name) + ", " + cause_index(type, cause_subindex(type, static_cast<uint8_t>(bit)));
  }
  return out;
}

std::string byte_text(EventType type, uint8_t byte) {
  return byte == 0 ? std::string("0") : std::to_string(byte) + " (" + byte_names(type, byte) + ")";
}

} // namespace

const CauseDefinition* find_cause(EventType type, uint8_t bit, uint8_t code) {
  for (const CauseDefinition& c : kCauses)
    if (c.type == type && c.bit == bit && c.code == code) return &c;
  return nullptr;
}

std::vector<const CauseDefinition*> causes_of_bit(EventType type, uint8_t bit) {
  std::vector<const CauseDefinition*> out;
  for (const CauseDefinition& c : kCauses)
    if (c.type == type && c.bit == bit) out.push_back(&c);
  return out;
}

const EventDefinition* find_event(uint16_t code) {
  for (const EventDefinition& e : kErrorEvents)
    if (e.code == code) return &e;
  for (const EventDefinition& e : kWarningEvents)
    if (e.code == code) return &e;
  return nullptr;
}

std::string_view bit_name(EventType type, uint8_t bit) {
  const auto causes = causes_of_bit(type, bit);
  if (causes.size() == 1) return causes.front()->name;
  return (type == EventType::Error ? kErrorBitNames : kWarningBitNames)[bit & 7u];
}

std::string cause_index(EventType type, uint8_t subindex) {
  return (type == EventType::Error ? "114." : "115.") + std::to_string(subindex);
}

// Manual 7.1: error bit 7 is 114.1 ... bit 0 is 114.8; warning bit 7 is 115.1.
uint8_t cause_subindex(EventType, uint8_t bit) { return static_cast<uint8_t>(8 - bit); }

std::string mid_sentence(std::string_view name) {
  std::string out(name);
  const std::string_view first = name.substr(0, name.find(' '));
  bool proper = first.size() > 1 && !std::islower(static_cast<unsigned char>(first[1]));
  for (std::size_t i = 1; i < first.size() && !proper; ++i) proper = std::isupper(static_cast<unsigned char>(first[i])) != 0;
  if (!out.empty() && !proper) out[0] = static_cast<char>(std::tolower(static_cast<unsigned char>(out[0])));
  return out;
}

std::string error_byte_names(uint8_t byte) { return byte_names(EventType::Error, byte); }
std::string warning_byte_names(uint8_t byte) { return byte_names(EventType::Warning, byte); }
std::string error_byte_text(uint8_t byte) { return byte_text(EventType::Error, byte); }
std::string warning_byte_text(uint8_t byte) { return byte_text(EventType::Warning, byte); }

} // namespace sreh
