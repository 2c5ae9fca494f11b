// The operations every front (HTTP, MQTT, Modbus) offers on a port, in one
// place so that all three answer alike: process data as raw frames and
// decoded fields, ISDU parameter access with raw wire values, fault
// injection. JSON in and out (nlohmann); the caller holds the port lock.
#pragma once
#include <cstdint>
#include <span>
#include <stdexcept>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "serve/hub.hpp"

namespace sreh::serve {

using Json = nlohmann::ordered_json;

// A request the server refuses before it reaches the twin (400-class):
// malformed JSON, wrong lengths, unknown keys, values out of range.
struct RequestError : std::runtime_error {
  RequestError(int status_, const std::string& what) : std::runtime_error(what), status(status_) {}
  int status;
};

// An ISDU the device refused: the IO-Link error code (iolink.md).
struct IsduRefused : std::runtime_error {
  IsduRefused(uint16_t code_, const std::string& what) : std::runtime_error(what), code(code_) {}
  uint16_t code;
};

std::string hex_bytes(std::span<const uint8_t> bytes);           // "0A1B", upper case
std::vector<uint8_t> parse_hex(const std::string& text, const std::string& what); // throws RequestError
std::string iolink_error_name(uint16_t code);                    // "Parameter value out of range"
std::string iolink_error_text(uint16_t code);                    // "0x8030"
int http_status_for(uint16_t iolink_code);                       // 404, 409 or 422

// Process data in is valid once the module has started up and exchanged
// since its last power-on (OPERATE, A-LINK-3), with the link up: never the
// stale frame of before a restart (issue 40).
bool pd_in_valid(Hub::Port& port);
// The faults injected now, in words ("link down", "supply 17 V", ...).
Json fault_injection_json(const Hub::Port& port);
// Also "state_write_error": null or why the last state-folder write failed.
Json port_summary(int p, Hub::Port& port);
Json processdata_json(Hub::Port& port);
// PUT processdata/out: {"raw": "<12 hex>"} or decoded fields (left-out
// fields keep their value), and/or {"valid": bool} (manual 5).
void apply_pd_out(Hub::Port& port, const Json& body);

// Parameter values (raw wire values, as a scenario's isdu_write).
Json parameter_json(uint16_t index, uint8_t subindex, std::span<const uint8_t> data);
// Bytes for a write: {"value": number | text | [numbers for a whole record]}
// or {"raw": "<hex>"}. Throws RequestError if the value does not fit its
// wire type (the parameter's own range is the device's to check).
std::vector<uint8_t> parameter_bytes(uint16_t index, uint8_t subindex, const Json& body);
// The PLC's ISDU access to a port (all fronts): 0x8020 (service temporarily
// not available) while the master still owes a replaced module its Data
// Storage restore, as a master whose port is not in OPERATE yet; else the
// device's own answer.
IsduResult port_isdu_read(Hub::Port& port, uint16_t index, uint8_t subindex);
IsduResult port_isdu_write(Hub::Port& port, uint16_t index, uint8_t subindex, std::span<const uint8_t> data);
// Throws IsduRefused with the device's code; the device stays unchanged.
Json read_parameter(Hub::Port& port, uint16_t index, uint8_t subindex);
Json write_parameter(Hub::Port& port, uint16_t index, uint8_t subindex, const Json& body);

// POST faults: any of link_up, supply_V, external_torque_Nm,
// flange_blocked, ambient_C, power_cycle. Checked completely before any is applied.
Json apply_faults(Hub::Port& port, const Json& body);
Json faults_json(const Hub::Port& port);

// Parses a request body as a JSON object (RequestError 400 otherwise).
Json parse_body(const std::string& body);

} // namespace sreh::serve
