// The state machine of manual 3.1/3.2 as a table: one row per transition,
// tagged with the manual's transition number or an ASSUMPTIONS.md entry
// (docs/style.md 3). Rows with a cause raise that error instead of moving.
#pragma once
#include <cstdint>
#include <optional>
#include <span>
#include <string_view>

#include "device_logic/device_types.hpp"
#include "device_logic/faults.hpp"

namespace sreh {

// What happened this IO-Link cycle (derived from process data edges) or this
// control step (motion finished, an error was raised).
enum class Event : uint8_t {
  SwitchOn,          // Motor On = 1, with Move, Error Reset, Set Origin = 0 (T1)
  SwitchOff,         // Motor On = 0 (T2, T9)
  MoveStart,         // Move rises, Stop = 0 (T3)
  MoveStartStopped,  // Move rises with Stop = 1: straight to Done (T3)
  StopMove,          // Stop rises while moving (T4)
  MotionComplete,    // positioning completed (T5)
  SetOrigin,         // Set Origin rises (T6)
  MoveReleased,      // Move falls (T7, or code 2 in Busy)
  SetOriginReleased, // Set Origin falls (T7)
  ErrorKeepsMotor,   // an error that leaves the motor on (T8.1)
  ErrorMotorOff,     // an error that switches the motor off (T8.2)
  ResetError,        // Error Reset rises (T10.1; T10.2 only with Motor On = 0)
};
std::string_view event_name(Event e);

constexpr uint8_t state_bit(State s) { return static_cast<uint8_t>(1u << static_cast<int>(s)); }
inline constexpr uint8_t kAnyState = 0x3F;
inline constexpr uint8_t kMotorOnStates =
    state_bit(State::Ready) | state_bit(State::Busy) | state_bit(State::Done) | state_bit(State::ErrorOn);
constexpr bool motor_is_on(State s) { return (kMotorOnStates & state_bit(s)) != 0; }

struct Transition {
  uint8_t from;              // state mask
  Event event;
  State to;                  // ignored when `raises` is set
  std::optional<ErrorBit> raises;
  uint8_t cause;             // cause code of the raised error
  std::string_view tag;      // "T3", "7.2 114.6/4", "A-SM-2", ...
};

std::span<const Transition> transition_table();

// The first row that matches (state, event), or nullptr: the event has no
// effect in that state.
const Transition* find_transition(State from, Event event);

} // namespace sreh
