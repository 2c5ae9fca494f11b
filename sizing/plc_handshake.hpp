// The PLC's side of a move, as both sizing evaluations (evaluate.cpp,
// cycle_evaluate.cpp) drive the twin (interfaces.md: the device only sees
// process data and ISDU; manual 3.2): Motor On with a set selected (T1),
// Move with a target until Done or an error (T3, T5), the move's record,
// Move dropped again (T7). One place, so that a single move and a cycle
// shake hands alike (issue 30).
#pragma once
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>

#include "twin/twin.hpp"

namespace sreh::sizing {

class PlcHandshake {
 public:
  explicit PlcHandshake(Twin& twin) : twin_(twin) {}

  // T1: Motor On with `set` selected, run until Ready or an error (at most
  // kSwitchOnCycles). Returns the reason when the motor did not switch on.
  std::optional<std::string> switch_on(uint8_t set);

  struct MoveEnd {
    bool ended = false;                // Done or an error came within max_cycles
    ProcessDataIn in;                  // the frame the move ended with
    std::optional<MoveRecord> record;  // the device's record of this Move (none if it refused it)
    std::size_t row_done = 0;          // trace rows when it ended
  };
  // T3: Move to `target` (wire counts, absolute or relative) with `set`,
  // run until Done or an error (T5), at most `max_cycles` IO-Link cycles.
  MoveEnd move(int32_t target, bool relative, uint8_t set, int max_cycles);

  // T7: Move low from the next cycle on (it must be low for at least one
  // cycle before the next command).
  void drop_move();

  // The last move's record as it is now: overshoot and the tolerance window
  // are still watched while the target is held (until the next Move).
  std::optional<MoveRecord> last_record() const;

 private:
  Twin& twin_;
  ProcessDataOut pd_;
  std::size_t records_before_ = 0; // twin.moves().size() before the last Move
};

} // namespace sreh::sizing
