#include "sizing/plc_handshake.hpp"

#include "sizing/run_parts.hpp"

namespace sreh::sizing {

std::optional<std::string> PlcHandshake::switch_on(uint8_t set) {
  pd_.motor_on = true;
  pd_.parameter_set = set;
  twin_.set_pd_out(pd_);
  const bool answered = run_until(twin_, [&] { return twin_.pd_in().ready || twin_.pd_in().error; }, kSwitchOnCycles);
  if (answered && twin_.pd_in().ready) return std::nullopt;
  return "motor did not switch on: " + error_text(twin_.pd_in().error_code);
}

PlcHandshake::MoveEnd PlcHandshake::move(int32_t target, bool relative, uint8_t set, int max_cycles) {
  pd_.target_raw = target;
  pd_.relative = relative;
  pd_.parameter_set = set;
  pd_.move = true;
  records_before_ = twin_.moves().size();
  twin_.set_pd_out(pd_);
  MoveEnd end;
  end.ended = run_until(twin_, [&] { const auto in = twin_.pd_in(); return in.done || in.error; }, max_cycles);
  end.in = twin_.pd_in();
  end.record = last_record();
  end.row_done = twin_.trace().size();
  return end;
}

void PlcHandshake::drop_move() {
  pd_.move = false;
  twin_.set_pd_out(pd_);
}

std::optional<MoveRecord> PlcHandshake::last_record() const {
  if (twin_.moves().size() > records_before_) return twin_.moves().back();
  return std::nullopt;
}

} // namespace sreh::sizing
