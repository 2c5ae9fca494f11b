#include "tools/master_log_stream.hpp"

#include "calibration/master_log.hpp"

namespace sreh::tools {
namespace {
constexpr uint16_t kTemperatureIndex = 112;       // manual 6.4: Temperature, UInt8
constexpr double kTemperatureC_per_raw = 0.5;     // manual 6.4: 0.5 degC per unit
} // namespace

MasterLogStream::MasterLogStream(const std::string& path) : file_(path) { write_master_log_header(file_.stream()); }

void MasterLogStream::attach(RunOptions& options) {
  options.trace_sink = [prev = std::move(options.trace_sink), this](const TraceRow& r) {
    if (prev) prev(r);
    row(r);
  };
  options.on_isdu_read = [prev = std::move(options.on_isdu_read), this](uint16_t index, uint8_t subindex,
                                                                        const IsduResult& result) {
    if (prev) prev(index, subindex, result);
    isdu_read(index, subindex, result);
  };
}

void MasterLogStream::row(const TraceRow& r) {
  write_master_log_row(file_.stream(), r.t_s, r.pd_out, r.pd_in, polled_temperature_C_);
  polled_temperature_C_.reset();
}

// The temperature the PLC polled goes on the next row the master records.
void MasterLogStream::isdu_read(uint16_t index, uint8_t subindex, const IsduResult& result) {
  if (index != kTemperatureIndex || subindex != 0 || !result.ok() || result.data.size() != 1) return;
  polled_temperature_C_ = kTemperatureC_per_raw * result.data[0];
}

} // namespace sreh::tools
