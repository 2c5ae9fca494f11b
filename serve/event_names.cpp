#include "serve/event_names.hpp"

#include <fmt/format.h>

#include "device_logic/fault_names.hpp"

namespace sreh::serve {

nlohmann::ordered_json describe_device_event(Twin& twin, uint16_t code) {
  using EventJson = nlohmann::ordered_json;
  const EventDefinition* e = find_event(code);
  if (e == nullptr) {
    return EventJson{{"name", fmt::format("event 0x{:04X}", code)}, {"index", nullptr}, {"cause_code", nullptr},
                {"remedy", nullptr}, {"label", fmt::format("event 0x{:04X}", code)}};
  }
  const uint8_t sub = cause_subindex(e->type, e->bit);
  const std::string index = cause_index(e->type, sub);
  const IsduResult r = twin.isdu_read(e->type == EventType::Error ? 114 : 115, sub);
  uint8_t now = r.ok() && r.data.size() == 1 ? r.data[0] : 0;
  if (e->cause_code != 0) now = e->cause_code; // 0x5110 / 0x5111: the event names its cause
  const CauseDefinition* c = find_cause(e->type, e->bit, now);
  if (c == nullptr) { // gone already, or an unlisted code: the only cause of the bit, if it has one
    const auto causes = causes_of_bit(e->type, e->bit);
    if (causes.size() == 1) c = causes.front();
  }
  const std::string name(c ? c->name : (e->type == EventType::Error ? kErrorBitNames : kWarningBitNames)[e->bit]);
  return EventJson{{"name", name},
              {"index", index},
              {"cause_code", c ? EventJson(c->code) : EventJson(nullptr)},
              {"remedy", c ? EventJson(std::string(c->remedy)) : EventJson(nullptr)},
              {"label", fmt::format("{} ({})", mid_sentence(name), index)}};
}

} // namespace sreh::serve
