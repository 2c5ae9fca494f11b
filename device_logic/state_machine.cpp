#include "device_logic/state_machine.hpp"

#include <array>

namespace sreh {
namespace {

constexpr uint8_t bit(State s) { return state_bit(s); }
constexpr uint8_t kOff = bit(State::MotorOff);
constexpr uint8_t kReady = bit(State::Ready);
constexpr uint8_t kBusy = bit(State::Busy);
constexpr uint8_t kDone = bit(State::Done);
constexpr uint8_t kErrOn = bit(State::ErrorOn);
constexpr uint8_t kErrOff = bit(State::ErrorOff);
constexpr uint8_t kNoError = kOff | kReady | kBusy | kDone;

using enum Event;
using E = ErrorBit;

// Order matters: the first matching row wins.
constexpr std::array kTransitions{
    Transition{kOff, SwitchOn, State::Ready, {}, 0, "T1"},
    Transition{kReady, SwitchOff, State::MotorOff, {}, 0, "T2"},
    // Switching off while a command runs is an invalid sequence (manual 7.2, 114.6 code 1).
    Transition{kBusy | kDone, SwitchOff, State::ErrorOff, E::InvalidCommand, cause::kMotorSwitchedOff, "7.2 114.6/1"},
    Transition{kErrOn, SwitchOff, State::ErrorOff, {}, 0, "T9"},
    Transition{kReady, MoveStart, State::Busy, {}, 0, "T3"},
    Transition{kReady, MoveStartStopped, State::Done, {}, 0, "T3 (Stop set)"},
    // Move from any other state, the error states included (manual 7.2, 114.6 code 4).
    Transition{kOff | kBusy | kDone | kErrOn | kErrOff, MoveStart, State::ErrorOff, E::InvalidCommand, cause::kMoveFromInvalidState, "7.2 114.6/4"},
    Transition{kOff | kBusy | kDone | kErrOn | kErrOff, MoveStartStopped, State::ErrorOff, E::InvalidCommand, cause::kMoveFromInvalidState, "7.2 114.6/4"},
    Transition{kBusy, StopMove, State::Busy, {}, 0, "T4"},
    Transition{kBusy, MotionComplete, State::Done, {}, 0, "T5"},
    Transition{kReady, SetOrigin, State::Done, {}, 0, "T6"},
    Transition{kOff | kBusy | kDone | kErrOn | kErrOff, SetOrigin, State::ErrorOff, E::InvalidCommand, cause::kSetOriginFromInvalidState, "7.2 114.6/5"},
    Transition{kDone, MoveReleased, State::Ready, {}, 0, "T7"},
    Transition{kDone, SetOriginReleased, State::Ready, {}, 0, "T7"},
    // Move released before Done (manual 7.2, 114.6 code 2).
    Transition{kBusy, MoveReleased, State::ErrorOn, E::InvalidCommand, cause::kOperationAborted, "7.2 114.6/2"},
    Transition{kReady | kBusy | kDone | kErrOn, ErrorKeepsMotor, State::ErrorOn, {}, 0, "T8.1"},
    Transition{kOff | kErrOff, ErrorKeepsMotor, State::ErrorOff, {}, 0, "T8.2 (motor already off)"},
    Transition{kAnyState, ErrorMotorOff, State::ErrorOff, {}, 0, "T8.2"},
    Transition{kErrOn, ResetError, State::Ready, {}, 0, "T10.1"},
    Transition{kErrOff, ResetError, State::MotorOff, {}, 0, "T10.2"},
};
static_assert(kNoError == 0x0F);

} // namespace

std::span<const Transition> transition_table() { return kTransitions; }

const Transition* find_transition(State from, Event event) {
  for (const auto& t : kTransitions) {
    if ((t.from & state_bit(from)) && t.event == event) return &t;
  }
  return nullptr;
}

std::string_view event_name(Event e) {
  switch (e) {
    case SwitchOn: return "SwitchOn";
    case SwitchOff: return "SwitchOff";
    case MoveStart: return "MoveStart";
    case MoveStartStopped: return "MoveStartStopped";
    case StopMove: return "StopMove";
    case MotionComplete: return "MotionComplete";
    case SetOrigin: return "SetOrigin";
    case MoveReleased: return "MoveReleased";
    case SetOriginReleased: return "SetOriginReleased";
    case ErrorKeepsMotor: return "ErrorKeepsMotor";
    case ErrorMotorOff: return "ErrorMotorOff";
    case ResetError: return "ResetError";
  }
  return "?";
}

std::string_view state_name(State s) {
  switch (s) {
    case State::MotorOff: return "MotorOff";
    case State::Ready: return "Ready";
    case State::Busy: return "Busy";
    case State::Done: return "Done";
    case State::ErrorOn: return "ErrorOn";
    case State::ErrorOff: return "ErrorOff";
  }
  return "?";
}

std::string_view led_name(LedColor c) {
  switch (c) {
    case LedColor::Off: return "off";
    case LedColor::Green: return "green";
    case LedColor::Yellow: return "yellow";
    case LedColor::Blue: return "blue";
    case LedColor::Red: return "red";
    case LedColor::Orange: return "orange";
    case LedColor::White: return "white";
    case LedColor::Violet: return "violet";
  }
  return "?";
}

// Manual 1: the IO-Link status LED's four states.
std::string_view iolink_led_name(IoLinkLedMode m) {
  switch (m) {
    case IoLinkLedMode::NotConnected: return "off";
    case IoLinkLedMode::Startup: return "startup";
    case IoLinkLedMode::Preoperate: return "preoperate";
    case IoLinkLedMode::Operate: return "operate";
  }
  return "?";
}

} // namespace sreh
