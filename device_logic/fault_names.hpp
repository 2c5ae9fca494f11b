// Look-ups in the one table of codes (issue 39): the causes of manual 7.2 /
// 7.3 and the events of index 37 (faults.hpp), the ISDU errors (isdu.hpp).
// Every output that shows a code shows its name from here.
#pragma once
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "device_logic/faults.hpp"

namespace sreh {

// The row of a cause; nullptr for a code the manual does not list.
const CauseDefinition* find_cause(EventType type, uint8_t bit, uint8_t code);
// The causes a bit of the error / warning byte stands for (manual 7.2, 7.3).
std::vector<const CauseDefinition*> causes_of_bit(EventType type, uint8_t bit);
// The event of index 37 with this code (faults.hpp); nullptr if none.
const EventDefinition* find_event(uint16_t code);
// A bit of the error / warning byte by name: its cause's where it has one
// ("Position tracking error", "Settling-timeout"), else the manual's name
// of the bit (2.4: "Invalid command / communication"); "" if unused.
std::string_view bit_name(EventType type, uint8_t bit);
// The index of a cause: "114.5" (error) or "115.3" (warning).
std::string cause_index(EventType type, uint8_t subindex);
// The subindex of 114 / 115 that holds the cause of a bit (manual 7.1).
uint8_t cause_subindex(EventType type, uint8_t bit);

// A name in the middle of a sentence: the first letter lower case unless the
// first word is a proper name ("SetOrigin", "IO-Link"): "position tracking
// error", "SetOrigin from invalid state".
std::string mid_sentence(std::string_view name);
// The bits set in an error / warning byte by name (bit_name) with their
// index, mid-sentence: "position tracking error, 114.5"; several
// joined by "; "; "" for 0.
std::string error_byte_names(uint8_t byte);
std::string warning_byte_names(uint8_t byte);
// "8 (position tracking error, 114.5)", "0": how the run output and JUnit
// print the process data's error / warning byte.
std::string error_byte_text(uint8_t byte);
std::string warning_byte_text(uint8_t byte);

} // namespace sreh
