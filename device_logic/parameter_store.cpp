// ParameterStore: ISDU access to the stored rows of the parameter table,
// block parameterisation (manual 6.6 commands 1..6), Data Storage index 3
// (manual 8) and the non-volatile image. Checks read ranges and lengths from
// the table only; the one cross-parameter rule is A-PARAM-6.
#include "device_logic/parameter_store.hpp"
#include "device_logic/byte_order.hpp"

#include <algorithm>

#include "device_logic/parameter_ids.hpp"
#include "device_logic/parameter_table.hpp"

namespace sreh {
namespace {

constexpr uint16_t kFirstTagIndex = 24;
constexpr std::array<uint8_t, 4> kImageMagic = {'S', 'R', 'N', 'V'};
constexpr uint16_t kImageVersion = 1;
constexpr uint8_t kImageFlagDsUpload = 0x01;
constexpr std::size_t kImageHeader = 4 + 2 + 1 + 2; // magic, version, flags, entry count
constexpr std::size_t kImageCrc = 4;

std::size_t pos_of(uint16_t index, uint8_t subindex) {
  return static_cast<std::size_t>(row_position(index, subindex)); // callers pass rows that exist
}

bool is_stored_numeric(const ParameterEntry& row) {
  return is_numeric(row.type) && (row.storage == Storage::Config || row.storage == Storage::PersistentDiag);
}
bool is_tag(const ParameterEntry& row) {
  return row.storage == Storage::Identification && row.access == Access::RW && row.type == ParamType::String;
}
std::size_t tag_slot(uint16_t index) { return static_cast<std::size_t>(index - kFirstTagIndex); }

uint16_t length_error(std::size_t got, std::size_t want) {
  return got > want ? kIsduLengthOverrun : kIsduLengthUnderrun;
}

// Length and value range of one numeric row (manual 6.2 ranges via the table).
uint16_t decode_checked(const ParameterEntry& row, std::span<const uint8_t> data, int64_t& value) {
  const std::size_t n = wire_size(row.type);
  if (data.size() != n) return length_error(data.size(), n);
  const int64_t v = decode_number(row.type, data);
  if (v < row.min || v > row.max) return kIsduValueOutOfRange;
  value = v;
  return kIsduOk;
}

// A-PARAM-6: the position limit's minimum must not exceed its maximum
// (manual 6.2 index 81), whether or not the limit is active.
bool consistent(const std::vector<int64_t>& numeric) {
  const ParamId lo = param::kPositionLimitMin, hi = param::kPositionLimitMax;
  return numeric[pos_of(lo.index, lo.subindex)] <= numeric[pos_of(hi.index, hi.subindex)];
}

void put_u16(std::vector<uint8_t>& out, uint16_t v) { be::append16(out, v); }
void put_u32(std::vector<uint8_t>& out, uint32_t v) { be::append32(out, v); }
uint16_t get_u16(std::span<const uint8_t> b, std::size_t at) { return be::read16(b, at); }
uint32_t get_u32(std::span<const uint8_t> b, std::size_t at) { return be::read32(b, at); }

std::vector<uint8_t> bytes_of(std::string_view s) { return {s.begin(), s.end()}; }

} // namespace

ParameterStore::ParameterStore() {
  const auto table = parameter_table();
  active_.numeric.resize(table.size(), 0);
  for (std::size_t i = 0; i < table.size(); ++i)
    if (is_numeric(table[i].type)) active_.numeric[i] = table[i].default_value;
  for (std::size_t k = 0; k < kTagCount; ++k)
    active_.tags[k] = std::string(find_parameter(static_cast<uint16_t>(kFirstTagIndex + k), 0)->default_text);
}

// ---------------------------------------------------------------- ISDU read

IsduResult ParameterStore::read(uint16_t index, uint8_t subindex) const {
  return read_from(active_, index, subindex);
}

IsduResult ParameterStore::read_from(const Values& v, uint16_t index, uint8_t subindex) const {
  if (!index_exists(index)) return isdu_error(kIsduIndexNotAvailable);
  if (subindex == 0 && is_record(index)) { // whole record, members in subindex order
    const auto members = record_members(index);
    for (const auto* m : members)
      if (m->access == Access::W) return isdu_error(kIsduAccessDenied);
    for (const auto* m : members)
      if (!is_numeric(m->type)) return isdu_error(kIsduSubindexNotAvailable);
    std::vector<uint8_t> out;
    for (const auto* m : members) {
      IsduResult part = read_from(v, index, m->subindex);
      if (!part.ok()) return part;
      out.insert(out.end(), part.data.begin(), part.data.end());
    }
    return isdu_data(std::move(out));
  }
  const ParameterEntry* row = find_parameter(index, subindex);
  if (row == nullptr) return isdu_error(kIsduSubindexNotAvailable);
  if (row->access == Access::W) return isdu_error(kIsduAccessDenied);
  if (index == kIndexDataStorage) {
    switch (subindex) {
      case 2: return isdu_data(encode_number(row->type, ds_state_property(ds_state_, ds_upload_flag_)));
      case 3: return isdu_data(encode_number(row->type, data_storage_size()));
      case 4: return isdu_data(encode_number(row->type, parameter_checksum()));
      case 5: return isdu_data(encode_index_list(data_storage_entries()));
      default: return isdu_error(kIsduSubindexNotAvailable);
    }
  }
  if (is_stored_numeric(*row)) return isdu_data(encode_number(row->type, v.numeric[pos_of(index, subindex)]));
  if (is_tag(*row)) return isdu_data(bytes_of(v.tags[tag_slot(index)]));
  if (row->storage == Storage::Identification) return isdu_data(bytes_of(row->default_text));
  return isdu_error(kIsduServiceTempUnavailable); // volatile: the Device answers these
}

// --------------------------------------------------------------- ISDU write

IsduResult ParameterStore::write(uint16_t index, uint8_t subindex, std::span<const uint8_t> data) {
  if (index == kIndexSystemCommand) { // manual 6.6: one uint8 command number
    if (subindex != 0) return isdu_error(kIsduSubindexNotAvailable);
    if (data.size() != 1) return isdu_error(length_error(data.size(), 1));
    return isdu_error(block_command(data[0]));
  }
  if (!index_exists(index)) return isdu_error(kIsduIndexNotAvailable);
  if (subindex == 0 && is_record(index)) return isdu_error(write_record(index, data));
  return isdu_error(write_row(index, subindex, data));
}

uint16_t ParameterStore::write_record(uint16_t index, std::span<const uint8_t> data) {
  const auto members = record_members(index);
  for (const auto* m : members)
    if (m->access != Access::RW) return kIsduAccessDenied;
  std::size_t total = 0;
  for (const auto* m : members) {
    if (!is_numeric(m->type)) return kIsduSubindexNotAvailable;
    total += wire_size(m->type);
  }
  if (data.size() != total) return length_error(data.size(), total);
  Values next = target();
  std::size_t offset = 0;
  for (const auto* m : members) {
    const std::size_t n = wire_size(m->type);
    int64_t value = 0;
    if (const uint16_t e = decode_checked(*m, data.subspan(offset, n), value); e != kIsduOk) return e;
    next.numeric[pos_of(index, m->subindex)] = value;
    offset += n;
  }
  return commit_single(std::move(next));
}

uint16_t ParameterStore::write_row(uint16_t index, uint8_t subindex, std::span<const uint8_t> data) {
  const ParameterEntry* row = find_parameter(index, subindex);
  if (row == nullptr) return kIsduSubindexNotAvailable;
  if (row->access == Access::R) return kIsduAccessDenied;
  if (index == kIndexDataStorage) { // 3.1 DS_Command, the only writable member
    int64_t cmd = 0;
    if (const uint16_t e = decode_checked(*row, data, cmd); e != kIsduOk) return e;
    return ds_command(static_cast<uint8_t>(cmd));
  }
  if (is_numeric(row->type) && row->storage == Storage::Config) {
    int64_t value = 0;
    if (const uint16_t e = decode_checked(*row, data, value); e != kIsduOk) return e;
    Values next = target();
    next.numeric[pos_of(index, subindex)] = value;
    return commit_single(std::move(next));
  }
  if (is_tag(*row)) { // manual 6.5: tags 24..26, 1..32 octets (A-PARAM-5)
    if (data.empty()) return kIsduLengthUnderrun;
    if (data.size() > row->max_length) return kIsduLengthOverrun;
    Values next = target();
    next.tags[tag_slot(index)] = std::string(data.begin(), data.end());
    return commit_single(std::move(next));
  }
  return kIsduAccessDenied;
}

ParameterStore::Values& ParameterStore::target() { return pending_ ? *pending_ : active_; }

uint16_t ParameterStore::commit_single(Values next) {
  if (pending_) { // block download: cross checks deferred to the end (iolink.md)
    *pending_ = std::move(next);
    return kIsduOk;
  }
  if (!consistent(next.numeric)) return kIsduInvalidParameterSet;
  apply(std::move(next));
  return kIsduOk;
}

void ParameterStore::apply(Values next) {
  if (next == active_) return;
  active_ = std::move(next);
  ++revision_;
}

// ------------------------------------------------- block parameterisation

uint16_t ParameterStore::block_command(uint8_t cmd) {
  switch (cmd) {
    case kCmdParamUploadStart:
      upload_open_ = true;
      return kIsduOk;
    case kCmdParamUploadEnd: // also ends an open download, discarding it (iolink.md)
      if (!pending_ && !upload_open_) return kIsduFunctionTempUnavailable;
      discard_download();
      upload_open_ = false;
      return kIsduOk;
    case kCmdParamDownloadStart: // a second start restarts the buffer (A-PARAM-8)
      pending_ = active_;
      return kIsduOk;
    case kCmdParamDownloadEnd:
      return end_download();
    case kCmdParamDownloadStore: {
      const uint16_t e = end_download();
      if (e == kIsduOk) ds_upload_flag_ = true;
      return e;
    }
    case kCmdParamBreak: // rollback: the applied set stays
      discard_download();
      upload_open_ = false;
      return kIsduOk;
    default:
      return kIsduFunctionUnavailable;
  }
}

uint16_t ParameterStore::end_download() {
  if (!pending_) return kIsduFunctionTempUnavailable;
  Values next = std::move(*pending_);
  pending_.reset();
  if (ds_state_ == DsState::Download) ds_state_ = DsState::Inactive;
  if (!consistent(next.numeric)) return kIsduInconsistentParameterSet; // old set stays
  apply(std::move(next));
  return kIsduOk;
}

bool ParameterStore::download_open() const { return pending_.has_value(); }
bool ParameterStore::upload_open() const { return upload_open_; }

void ParameterStore::discard_download() {
  pending_.reset();
  if (ds_state_ == DsState::Download) ds_state_ = DsState::Inactive;
}

void ParameterStore::abort_block() {
  pending_.reset();
  upload_open_ = false;
  ds_state_ = DsState::Inactive;
}

// ------------------------------------------------------------ Data Storage

uint16_t ParameterStore::ds_command(uint8_t cmd) {
  switch (static_cast<DsCommand>(cmd)) {
    case DsCommand::UploadStart:
      ds_state_ = DsState::Upload;
      return kIsduOk;
    case DsCommand::UploadEnd: // the master holds the set now
      if (ds_state_ != DsState::Upload) return kIsduFunctionTempUnavailable;
      ds_state_ = DsState::Inactive;
      ds_upload_flag_ = false;
      return kIsduOk;
    case DsCommand::DownloadStart:
      pending_ = active_;
      ds_state_ = DsState::Download;
      return kIsduOk;
    case DsCommand::DownloadEnd: {
      if (ds_state_ != DsState::Download) return kIsduFunctionTempUnavailable;
      const uint16_t e = end_download();
      if (e == kIsduOk) ds_upload_flag_ = false; // device now holds the master's set
      return e;
    }
    case DsCommand::Break:
      if (ds_state_ == DsState::Download) pending_.reset();
      ds_state_ = DsState::Inactive;
      return kIsduOk;
  }
  return kIsduValueOutOfRange; // unreachable: the table limits 3.1 to 1..5
}

std::vector<uint8_t> ParameterStore::ds_set_bytes() const {
  std::vector<uint8_t> out;
  for (const auto& e : data_storage_entries()) {
    const IsduResult r = read(e.index, e.subindex);
    put_u16(out, e.index);
    out.push_back(e.subindex);
    out.push_back(static_cast<uint8_t>(r.data.size()));
    out.insert(out.end(), r.data.begin(), r.data.end());
  }
  return out;
}

uint32_t ParameterStore::parameter_checksum() const { return crc32(ds_set_bytes()); }
uint32_t ParameterStore::data_storage_size() const { return static_cast<uint32_t>(ds_set_bytes().size()); }
bool ParameterStore::ds_upload_requested() const { return ds_upload_flag_; }
void ParameterStore::clear_ds_upload_request() { ds_upload_flag_ = false; }
void ParameterStore::request_ds_upload() { ds_upload_flag_ = true; }
DsState ParameterStore::ds_state() const { return ds_state_; }
uint64_t ParameterStore::config_revision() const { return revision_; }

// ------------------------------------------------------- resets, accessors

void ParameterStore::factory_reset(bool keep_tags) {
  abort_block();
  const auto table = parameter_table();
  Values next = active_;
  for (std::size_t i = 0; i < table.size(); ++i)
    if (table[i].storage == Storage::Config && is_numeric(table[i].type)) next.numeric[i] = table[i].default_value;
  if (!keep_tags) next.tags = ParameterStore{}.active_.tags;
  apply(std::move(next));
  ds_upload_flag_ = keep_tags; // 129 requests an upload; 130/131 must not (iolink.md)
}

MotionParameterSet ParameterStore::motion_set(int n) const {
  const param::MotionSet set(std::clamp(n, 0, param::kMotionSets - 1));
  const auto table = parameter_table();
  const auto display = [&](ParamId id) {
    const std::size_t p = pos_of(id.index, id.subindex);
    return static_cast<double>(active_.numeric[p]) * table[p].display_scale;
  };
  const ParamId active = set.settling_timeout_active;
  return MotionParameterSet{display(set.speed),       display(set.acceleration), display(set.jerk),
                            display(set.load),        display(set.tolerance),    display(set.waiting_time),
                            display(set.settling_timeout), active_.numeric[pos_of(active.index, active.subindex)] != 0};
}

int64_t ParameterStore::raw(uint16_t index, uint8_t subindex) const {
  const int p = row_position(index, subindex);
  if (p < 0) return 0;
  return active_.numeric[static_cast<std::size_t>(p)]; // non-stored numeric rows hold their default
}

void ParameterStore::set_raw_internal(uint16_t index, uint8_t subindex, int64_t raw_value) {
  const ParameterEntry* row = find_parameter(index, subindex);
  if (row == nullptr || !is_stored_numeric(*row)) return;
  const int64_t v = std::clamp(raw_value, row->min, row->max);
  int64_t& slot = active_.numeric[pos_of(index, subindex)];
  if (slot == v) return;
  slot = v;
  if (row->storage == Storage::Config) { // a local change (e.g. 171): master should upload
    ++revision_;
    ds_upload_flag_ = true;
  }
}

std::string ParameterStore::tag(uint16_t index) const {
  if (index < kFirstTagIndex || index >= kFirstTagIndex + kTagCount) return {};
  return active_.tags[tag_slot(index)];
}

bool ParameterStore::same_configuration(const ParameterStore& other) const {
  if (active_.tags != other.active_.tags) return false;
  const auto table = parameter_table();
  for (std::size_t i = 0; i < table.size(); ++i)
    if (table[i].storage == Storage::Config && active_.numeric[i] != other.active_.numeric[i]) return false;
  return true;
}

bool ParameterStore::operator==(const ParameterStore& other) const {
  return active_ == other.active_ && pending_ == other.pending_ && upload_open_ == other.upload_open_ &&
         ds_state_ == other.ds_state_ && ds_upload_flag_ == other.ds_upload_flag_;
}

// ------------------------------------------------- non-volatile memory image
// Layout (big-endian): "SRNV", version u16, flags u8 (bit 0 DS upload
// request), entry count u16, entries {index u16, subindex u8, length u8,
// data}, CRC-32 u32 over everything before it.

std::vector<uint8_t> ParameterStore::image() const {
  std::vector<uint8_t> out(kImageMagic.begin(), kImageMagic.end());
  put_u16(out, kImageVersion);
  out.push_back(ds_upload_flag_ ? kImageFlagDsUpload : 0);
  const std::size_t count_at = out.size();
  put_u16(out, 0);
  uint16_t count = 0;
  for (const auto& row : parameter_table()) {
    if (!is_stored_numeric(row) && !is_tag(row)) continue;
    const IsduResult r = read(row.index, row.subindex);
    put_u16(out, row.index);
    out.push_back(row.subindex);
    out.push_back(static_cast<uint8_t>(r.data.size()));
    out.insert(out.end(), r.data.begin(), r.data.end());
    ++count;
  }
  be::write(std::span<uint8_t>(out).subspan(count_at, 2), count);
  put_u32(out, crc32(out));
  return out;
}

std::optional<ParameterStore> ParameterStore::from_image(std::span<const uint8_t> bytes) {
  if (bytes.size() < kImageHeader + kImageCrc) return std::nullopt;
  if (!std::equal(kImageMagic.begin(), kImageMagic.end(), bytes.begin())) return std::nullopt;
  if (get_u16(bytes, 4) != kImageVersion) return std::nullopt;
  const std::size_t body_end = bytes.size() - kImageCrc;
  if (crc32(bytes.first(body_end)) != get_u32(bytes, body_end)) return std::nullopt;
  const uint8_t flags = bytes[6];
  if ((flags & ~kImageFlagDsUpload) != 0) return std::nullopt;

  ParameterStore store;
  std::vector<bool> seen(parameter_row_count(), false);
  const uint16_t count = get_u16(bytes, 7);
  std::size_t at = kImageHeader;
  for (uint16_t k = 0; k < count; ++k) {
    if (at + 4 > body_end) return std::nullopt;
    const uint16_t index = get_u16(bytes, at);
    const uint8_t sub = bytes[at + 2];
    const std::size_t len = bytes[at + 3];
    at += 4;
    if (at + len > body_end) return std::nullopt;
    const auto data = bytes.subspan(at, len);
    at += len;
    const int p = row_position(index, sub);
    if (p < 0 || seen[static_cast<std::size_t>(p)]) return std::nullopt;
    seen[static_cast<std::size_t>(p)] = true;
    const ParameterEntry& row = parameter_table()[static_cast<std::size_t>(p)];
    if (is_stored_numeric(row)) {
      int64_t value = 0;
      if (decode_checked(row, data, value) != kIsduOk) return std::nullopt;
      store.active_.numeric[static_cast<std::size_t>(p)] = value;
    } else if (is_tag(row)) {
      if (len == 0 || len > row.max_length) return std::nullopt;
      store.active_.tags[tag_slot(index)] = std::string(data.begin(), data.end());
    } else {
      return std::nullopt; // not a non-volatile row
    }
  }
  if (at != body_end) return std::nullopt;
  if (!consistent(store.active_.numeric)) return std::nullopt;
  store.ds_upload_flag_ = (flags & kImageFlagDsUpload) != 0;
  return store;
}

} // namespace sreh
