// ParameterStore: ISDU access (manual 6) and block parameterisation (6.6
// commands 1..6); the image and Data Storage: parameter_store_image_test.cpp.
#include "device_logic/parameter_store.hpp"

#include <gtest/gtest.h>

#include <cstdint>
#include <string>
#include <vector>

#include "device_logic/parameter_table.hpp"
#include "parameter_store_helpers.hpp"

namespace sreh {
namespace {

using namespace store_test;

// manual 6.2: every stored row reads its default after construction.
TEST(ParameterStore, FactoryDefaultsReadBackOverIsdu) {
  const ParameterStore s;
  for (const auto& row : parameter_table()) {
    if (!is_numeric(row.type) || (row.storage != Storage::Config && row.storage != Storage::PersistentDiag))
      continue;
    EXPECT_EQ(read_num(s, row.index, row.subindex), row.default_value) << row.index << "." << int(row.subindex);
    EXPECT_EQ(s.raw(row.index, row.subindex), row.default_value);
  }
  EXPECT_EQ(s.read(64, 1).data, u16(300));   // 30 deg/s, set 0
  EXPECT_EQ(s.read(71, 1).data, u16(30000)); // 3000 deg/s, sets 1..7
  EXPECT_EQ(s.read(81, 2).data, i32(65536)); // 360 deg
  EXPECT_FALSE(s.download_open());
  EXPECT_FALSE(s.ds_upload_requested());
}

// manual 3.5 in display units.
TEST(ParameterStore, MotionSetInDisplayUnits) {
  ParameterStore s;
  const MotionParameterSet m0 = s.motion_set(0);
  EXPECT_DOUBLE_EQ(m0.speed_dps, 30.0);
  EXPECT_DOUBLE_EQ(m0.accel_pct, 100.0);
  EXPECT_DOUBLE_EQ(m0.jerk_pct, 100.0);
  EXPECT_DOUBLE_EQ(m0.load_gcm2, 0.0);
  EXPECT_NEAR(m0.tolerance_deg, 0.1, 0.0005);
  EXPECT_DOUBLE_EQ(m0.wait_ms, 25.0);
  EXPECT_DOUBLE_EQ(m0.settling_timeout_ms, 100.0);
  EXPECT_TRUE(m0.timeout_enabled);
  EXPECT_DOUBLE_EQ(s.motion_set(7).speed_dps, 3000.0);

  ASSERT_EQ(put(s, 67, 1, 12345), kIsduOk);
  ASSERT_EQ(put(s, 67, 4, 2000), kIsduOk);
  ASSERT_EQ(put(s, 67, 8, 0), kIsduOk);
  const MotionParameterSet m3 = s.motion_set(3);
  EXPECT_DOUBLE_EQ(m3.speed_dps, 1234.5);
  EXPECT_DOUBLE_EQ(m3.load_gcm2, 2000.0);
  EXPECT_FALSE(m3.timeout_enabled);
}

// One refused write each, with the ISDU code iolink.md assigns.
struct Refusal {
  const char* what;
  uint16_t index;
  uint8_t sub;
  Bytes data;
  uint16_t error;
};

std::vector<Refusal> refusals() {
  return {
      {"index does not exist", 84, 0, u8(1), kIsduIndexNotAvailable},
      {"index 999", 999, 0, u8(1), kIsduIndexNotAvailable},
      {"subindex of a record missing", 64, 9, u16(1), kIsduSubindexNotAvailable},
      {"subindex on a plain variable", 82, 1, u8(1), kIsduSubindexNotAvailable},
      {"system command with subindex", 2, 1, u8(3), kIsduSubindexNotAvailable},
      {"6.3 persistent read-only", 96, 0, encode_number(ParamType::UInt32, 5), kIsduAccessDenied},
      {"6.3 record read-only", 97, 0, Bytes(12, 0), kIsduAccessDenied},
      {"6.5 identification read-only", 16, 0, str("Other"), kIsduAccessDenied},
      {"6.4 volatile read-only", 112, 0, u8(50), kIsduAccessDenied},
      {"DS state read-only", 3, 2, u8(0), kIsduAccessDenied},
      {"speed 0 below 0.1 deg/s", 64, 1, u16(0), kIsduValueOutOfRange},
      {"speed above 4300 deg/s", 64, 1, u16(43001), kIsduValueOutOfRange},
      {"accel 0", 65, 2, u16(0), kIsduValueOutOfRange},
      {"jerk above 100 %", 65, 3, u16(1001), kIsduValueOutOfRange},
      {"load above 15000", 66, 4, u16(15001), kIsduValueOutOfRange},
      {"wait above 5 s", 66, 6, u16(50001), kIsduValueOutOfRange},
      {"timeout above 5 s", 66, 7, u16(50001), kIsduValueOutOfRange},
      {"timeout enable 2", 66, 8, u8(2), kIsduValueOutOfRange},
      {"limit active 2", 81, 3, u8(2), kIsduValueOutOfRange},
      {"direction 2", 82, 0, u8(2), kIsduValueOutOfRange},
      {"LED mode 3", 83, 0, u8(3), kIsduValueOutOfRange},
      {"voltage min below 16 V", 85, 1, u16(15999), kIsduValueOutOfRange},
      {"voltage min above 23 V", 85, 1, u16(23001), kIsduValueOutOfRange},
      {"voltage max below 25 V", 85, 2, u16(24999), kIsduValueOutOfRange},
      {"voltage max above 32 V", 85, 2, u16(32001), kIsduValueOutOfRange},
      {"zero above 720 deg", 86, 0, i32(131073), kIsduValueOutOfRange},
      {"zero below -720 deg", 86, 0, i32(-131073), kIsduValueOutOfRange},
      {"tracking error 0", 87, 1, u16(0), kIsduValueOutOfRange},
      {"tracking error above 90 deg", 87, 1, u16(901), kIsduValueOutOfRange},
      {"DS command 6", 3, 1, u8(6), kIsduValueOutOfRange},
      {"DS command 0", 3, 1, u8(0), kIsduValueOutOfRange},
      {"record member out of range", 64, 0, cat({u16(0), u16(1000), u16(1000), u16(0), u16(146), u16(250), u16(1000), u8(1)}), kIsduValueOutOfRange},
      {"uint16 with 3 octets", 64, 1, Bytes{0, 1, 0}, kIsduLengthOverrun},
      {"uint8 with 2 octets", 82, 0, u16(1), kIsduLengthOverrun},
      {"tag of 33 octets", 24, 0, Bytes(33, 'x'), kIsduLengthOverrun},
      {"record with 16 octets", 64, 0, Bytes(16, 1), kIsduLengthOverrun},
      {"system command 2 octets", 2, 0, u16(3), kIsduLengthOverrun},
      {"uint16 with 1 octet", 64, 1, u8(5), kIsduLengthUnderrun},
      {"int32 with 2 octets", 86, 0, u16(5), kIsduLengthUnderrun},
      {"empty tag", 25, 0, Bytes{}, kIsduLengthUnderrun},
      {"record with 14 octets", 64, 0, Bytes(14, 1), kIsduLengthUnderrun},
      {"empty system command", 2, 0, Bytes{}, kIsduLengthUnderrun},
      {"unknown system command 7", 2, 0, u8(7), kIsduFunctionUnavailable},
      {"Device's own command 128 is not the store's", 2, 0, u8(128), kIsduFunctionUnavailable},
      {"ParamDownloadEnd without start", 2, 0, u8(kCmdParamDownloadEnd), kIsduFunctionTempUnavailable},
      {"ParamDownloadStore without start", 2, 0, u8(kCmdParamDownloadStore), kIsduFunctionTempUnavailable},
      {"ParamUploadEnd without start", 2, 0, u8(kCmdParamUploadEnd), kIsduFunctionTempUnavailable},
      {"DS DownloadEnd without start", 3, 1, u8(4), kIsduFunctionTempUnavailable},
      {"DS UploadEnd without start", 3, 1, u8(2), kIsduFunctionTempUnavailable},
      {"81.1 above 81.2", 81, 1, i32(65537), kIsduInvalidParameterSet},
      {"81.2 below 81.1", 81, 2, i32(-1), kIsduInvalidParameterSet},
      {"record 81 min above max", 81, 0, cat({i32(10), i32(5), u8(1)}), kIsduInvalidParameterSet},
  };
}

// iolink.md: a refused write changes nothing (the whole store compared).
TEST(ParameterStore, EveryRefusedWriteHasItsCodeAndChangesNothing) {
  ParameterStore s;
  ASSERT_EQ(s.write(24, 0, str("cell 7")).error, kIsduOk); // non-default content
  ASSERT_EQ(put(s, 65, 4, 1234), kIsduOk);
  for (const auto& r : refusals()) {
    SCOPED_TRACE(r.what);
    const ParameterStore before = s;
    const auto image_before = s.image();
    const auto revision_before = s.config_revision();
    const IsduResult result = s.write(r.index, r.sub, r.data);
    EXPECT_EQ(result.error, r.error);
    EXPECT_TRUE(result.data.empty());
    EXPECT_TRUE(s == before);
    EXPECT_EQ(s.image(), image_before);
    EXPECT_EQ(s.config_revision(), revision_before);
  }
}

TEST(ParameterStore, ReadErrors) {
  const ParameterStore s;
  EXPECT_EQ(s.read(999, 0).error, kIsduIndexNotAvailable);
  EXPECT_EQ(s.read(1, 0).error, kIsduIndexNotAvailable);
  EXPECT_EQ(s.read(64, 9).error, kIsduSubindexNotAvailable);
  EXPECT_EQ(s.read(86, 1).error, kIsduSubindexNotAvailable);
  EXPECT_EQ(s.read(2, 0).error, kIsduAccessDenied);   // system command is write-only
  EXPECT_EQ(s.read(3, 1).error, kIsduAccessDenied);   // DS_Command is write-only
  EXPECT_EQ(s.read(3, 0).error, kIsduAccessDenied);   // record with a write-only member
  EXPECT_EQ(s.read(112, 0).error, kIsduServiceTempUnavailable); // the Device answers 6.4
  EXPECT_TRUE(s.read(999, 0).data.empty());
}

// A value equal to its range limits is accepted (manual 6.2 ranges inclusive).
TEST(ParameterStore, RangeLimitsInclusive) {
  ParameterStore s;
  for (const auto& row : parameter_table()) {
    if (row.storage != Storage::Config || row.index == 81) continue; // 81: cross-checked below
    for (int64_t v : {row.min, row.max}) {
      EXPECT_EQ(put(s, row.index, row.subindex, v), kIsduOk) << row.index << "." << int(row.subindex);
      EXPECT_EQ(s.raw(row.index, row.subindex), v);
    }
  }
  EXPECT_EQ(put(s, 81, 1, 65536), kIsduOk); // 81.1 == 81.2 allowed
}

// Record subindex 0: members concatenated big-endian in subindex order (iolink.md).
TEST(ParameterStore, RecordSubindexZeroReadAndWrite) {
  ParameterStore s;
  const Bytes set0 = cat({u16(300), u16(1000), u16(1000), u16(0), u16(146), u16(250), u16(1000), u8(1)});
  EXPECT_EQ(s.read(64, 0).data, set0);
  EXPECT_EQ(s.read(81, 0).data, cat({i32(0), i32(65536), u8(0)}));
  EXPECT_EQ(s.read(97, 0).data, Bytes(12, 0));
  EXPECT_EQ(s.read(98, 0).data.size(), 5u);

  const Bytes set5 = cat({u16(500), u16(200), u16(300), u16(4000), u16(1000), u16(100), u16(20000), u8(0)});
  ASSERT_EQ(s.write(69, 0, set5).error, kIsduOk);
  EXPECT_EQ(s.read(69, 0).data, set5);
  EXPECT_EQ(read_num(s, 69, 4), 4000);
  EXPECT_DOUBLE_EQ(s.motion_set(5).settling_timeout_ms, 2000.0);
  EXPECT_FALSE(s.motion_set(5).timeout_enabled);

  ASSERT_EQ(s.write(81, 0, cat({i32(-65536), i32(131072), u8(1)})).error, kIsduOk);
  EXPECT_EQ(s.raw(81, 1), -65536);
  EXPECT_EQ(s.raw(81, 3), 1);
}

// manual 6.5: tags 24..26 rw strings up to 32 octets; identification read-only.
TEST(ParameterStore, Strings) {
  ParameterStore s;
  EXPECT_EQ(s.read(24, 0).data, str("***"));
  EXPECT_EQ(s.read(16, 0).data, str("Afag"));
  EXPECT_EQ(s.read(19, 0).data, str("SREH-50-IOL"));
  EXPECT_EQ(s.read(13, 0).data, (Bytes{0x40, 0x00, 0x81, 0x01, 0x00, 0x31}));
  const std::string max32(32, 'L');
  ASSERT_EQ(s.write(26, 0, str(max32)).error, kIsduOk);
  EXPECT_EQ(s.read(26, 0).data, str(max32));
  ASSERT_EQ(s.write(25, 0, str("x")).error, kIsduOk);
  EXPECT_EQ(s.tag(25), "x");
  EXPECT_EQ(s.read(25, 0).data, str("x")); // no padding
}

// iolink.md: single writes apply at once and do not request a DS upload.
TEST(ParameterStore, SingleWriteAppliesAndAdvancesRevision) {
  ParameterStore s;
  const uint64_t r0 = s.config_revision();
  const uint32_t c0 = s.parameter_checksum();
  ASSERT_EQ(put(s, 83, 0, 2), kIsduOk);
  EXPECT_EQ(s.raw(83, 0), 2);
  EXPECT_EQ(s.config_revision(), r0 + 1);
  EXPECT_NE(s.parameter_checksum(), c0);
  EXPECT_FALSE(s.ds_upload_requested());
  ASSERT_EQ(put(s, 83, 0, 2), kIsduOk); // same value: no change
  EXPECT_EQ(s.config_revision(), r0 + 1);
  ASSERT_EQ(s.write(24, 0, str("A")).error, kIsduOk); // tags are in the DS set
  EXPECT_EQ(s.config_revision(), r0 + 2);
}

// manual 6.6 cmds 3 + 4: writes buffered, applied at the end.
TEST(ParameterStore, BlockDownloadAppliesAtEnd) {
  ParameterStore s;
  ASSERT_EQ(cmd(s, kCmdParamDownloadStart), kIsduOk);
  EXPECT_TRUE(s.download_open());
  ASSERT_EQ(put(s, 64, 1, 1000), kIsduOk);
  ASSERT_EQ(s.write(24, 0, str("block")).error, kIsduOk);
  EXPECT_EQ(s.raw(64, 1), 300);         // not yet applied
  EXPECT_EQ(read_num(s, 64, 1), 300);   // reads show the applied set (A-PARAM-8)
  EXPECT_EQ(put(s, 64, 1, 0), kIsduValueOutOfRange); // per-value checks still apply
  const uint64_t r0 = s.config_revision();
  ASSERT_EQ(cmd(s, kCmdParamDownloadEnd), kIsduOk);
  EXPECT_FALSE(s.download_open());
  EXPECT_EQ(s.raw(64, 1), 1000);
  EXPECT_EQ(s.tag(24), "block");
  EXPECT_EQ(s.config_revision(), r0 + 1); // one change for the whole block
  EXPECT_FALSE(s.ds_upload_requested());
}

// iolink.md: cross-parameter checks are deferred while a download is open.
TEST(ParameterStore, BlockDownloadDefersCrossChecks) {
  ParameterStore s;
  // Moving the limit window to [1000 deg, 2000 deg]: min first would collide as a single write.
  EXPECT_EQ(put(s, 81, 1, 1000 * 65536 / 360), kIsduInvalidParameterSet);
  ASSERT_EQ(cmd(s, kCmdParamDownloadStart), kIsduOk);
  ASSERT_EQ(put(s, 81, 1, 1000 * 65536 / 360), kIsduOk);
  ASSERT_EQ(put(s, 81, 2, 2000 * 65536 / 360), kIsduOk);
  ASSERT_EQ(cmd(s, kCmdParamDownloadEnd), kIsduOk);
  EXPECT_EQ(s.raw(81, 1), 1000 * 65536 / 360);
  EXPECT_EQ(s.raw(81, 2), 2000 * 65536 / 360);
}

// iolink.md cmd 4: inconsistent set -> 0x8041, buffer discarded, old set stays.
TEST(ParameterStore, InconsistentBlockDownloadRollsBack) {
  ParameterStore s;
  ASSERT_EQ(put(s, 70, 4, 777), kIsduOk);
  const ParameterStore before = s;
  const uint64_t r0 = s.config_revision();
  ASSERT_EQ(cmd(s, kCmdParamDownloadStart), kIsduOk);
  ASSERT_EQ(put(s, 64, 1, 5000), kIsduOk);
  ASSERT_EQ(put(s, 81, 1, 100000), kIsduOk); // > 81.2, accepted while buffered
  EXPECT_EQ(cmd(s, kCmdParamDownloadEnd), kIsduInconsistentParameterSet);
  EXPECT_FALSE(s.download_open());
  EXPECT_TRUE(s == before);
  EXPECT_EQ(s.config_revision(), r0);
  // Same with ParamDownloadStore: no upload request either.
  ASSERT_EQ(cmd(s, kCmdParamDownloadStart), kIsduOk);
  ASSERT_EQ(put(s, 81, 2, -5), kIsduOk);
  EXPECT_EQ(cmd(s, kCmdParamDownloadStore), kIsduInconsistentParameterSet);
  EXPECT_TRUE(s == before);
  EXPECT_FALSE(s.ds_upload_requested());
}

// iolink.md cmd 6 ParamBreak: rollback.
TEST(ParameterStore, ParamBreakRollsBack) {
  ParameterStore s;
  const ParameterStore before = s;
  ASSERT_EQ(cmd(s, kCmdParamDownloadStart), kIsduOk);
  ASSERT_EQ(put(s, 65, 1, 1), kIsduOk);
  ASSERT_EQ(s.write(26, 0, str("gone")).error, kIsduOk);
  ASSERT_EQ(cmd(s, kCmdParamBreak), kIsduOk);
  EXPECT_TRUE(s == before);
  EXPECT_EQ(cmd(s, kCmdParamDownloadEnd), kIsduFunctionTempUnavailable);
}

// iolink.md: communication loss or a reset discards an open download.
TEST(ParameterStore, AbortBlockDiscardsDownload) {
  ParameterStore s;
  const ParameterStore before = s;
  ASSERT_EQ(cmd(s, kCmdParamDownloadStart), kIsduOk);
  ASSERT_EQ(put(s, 82, 0, 1), kIsduOk);
  s.abort_block();
  EXPECT_TRUE(s == before);
  EXPECT_EQ(s.raw(82, 0), 0);
}

// A second ParamDownloadStart restarts the buffer (A-PARAM-8).
TEST(ParameterStore, SecondDownloadStartRestartsBuffer) {
  ParameterStore s;
  ASSERT_EQ(cmd(s, kCmdParamDownloadStart), kIsduOk);
  ASSERT_EQ(put(s, 82, 0, 1), kIsduOk);
  ASSERT_EQ(cmd(s, kCmdParamDownloadStart), kIsduOk);
  ASSERT_EQ(put(s, 83, 0, 0), kIsduOk);
  ASSERT_EQ(cmd(s, kCmdParamDownloadEnd), kIsduOk);
  EXPECT_EQ(s.raw(82, 0), 0);
  EXPECT_EQ(s.raw(83, 0), 0);
}

// iolink.md cmd 5: as 4, and on success a Data Storage upload request.
TEST(ParameterStore, DownloadStoreRequestsUpload) {
  ParameterStore s;
  ASSERT_EQ(cmd(s, kCmdParamDownloadStart), kIsduOk);
  ASSERT_EQ(put(s, 87, 1, 50), kIsduOk);
  ASSERT_EQ(cmd(s, kCmdParamDownloadStore), kIsduOk);
  EXPECT_EQ(s.raw(87, 1), 50);
  EXPECT_TRUE(s.ds_upload_requested());
  EXPECT_EQ(read_num(s, 3, 2) & 0x80, 0x80); // State_Property bit 7
  s.clear_ds_upload_request();
  EXPECT_FALSE(s.ds_upload_requested());
}

// iolink.md cmds 1, 2: block upload; UploadEnd also ends an open download.
TEST(ParameterStore, BlockUpload) {
  ParameterStore s;
  const ParameterStore before = s;
  ASSERT_EQ(cmd(s, kCmdParamUploadStart), kIsduOk);
  EXPECT_TRUE(s.upload_open());
  EXPECT_EQ(read_num(s, 64, 1), 300); // reads work during the upload
  EXPECT_EQ(s.read(65, 0).data.size(), 15u);
  ASSERT_EQ(cmd(s, kCmdParamUploadEnd), kIsduOk);
  EXPECT_FALSE(s.upload_open());
  EXPECT_EQ(cmd(s, kCmdParamUploadEnd), kIsduFunctionTempUnavailable);
  ASSERT_EQ(cmd(s, kCmdParamDownloadStart), kIsduOk);
  ASSERT_EQ(put(s, 82, 0, 1), kIsduOk);
  ASSERT_EQ(cmd(s, kCmdParamUploadEnd), kIsduOk);
  EXPECT_FALSE(s.download_open());
  EXPECT_TRUE(s == before);
  EXPECT_EQ(s.block_command(0), kIsduFunctionUnavailable);
  EXPECT_EQ(s.block_command(160), kIsduFunctionUnavailable);
}

// iolink.md: 129 keeps tags and requests an upload; 130/131 reset tags, no request.
TEST(ParameterStore, FactoryReset) {
  ParameterStore s;
  ASSERT_EQ(put(s, 66, 1, 111), kIsduOk);
  ASSERT_EQ(put(s, 86, 0, -1000), kIsduOk);
  ASSERT_EQ(s.write(24, 0, str("keep me")).error, kIsduOk);
  s.set_raw_internal(96, 0, 42); // persistent diagnostics survive (manual 6.3)
  ASSERT_EQ(cmd(s, kCmdParamDownloadStart), kIsduOk);

  ParameterStore app = s;
  app.factory_reset(/*keep_tags=*/true);
  EXPECT_FALSE(app.download_open());
  EXPECT_EQ(app.raw(66, 1), 30000);
  EXPECT_EQ(app.raw(86, 0), 0);
  EXPECT_EQ(app.tag(24), "keep me");
  EXPECT_EQ(app.raw(96, 0), 42);
  EXPECT_TRUE(app.ds_upload_requested());

  ParameterStore factory = s;
  factory.request_ds_upload();
  factory.factory_reset(/*keep_tags=*/false);
  EXPECT_EQ(factory.tag(24), "***");
  EXPECT_EQ(factory.raw(96, 0), 42);
  EXPECT_FALSE(factory.ds_upload_requested());
  EXPECT_TRUE(factory.same_configuration(ParameterStore{}));
}

TEST(ParameterStore, SetRawInternal) {
  ParameterStore s;
  const uint64_t r0 = s.config_revision();
  s.set_raw_internal(97, 1, 600);
  EXPECT_EQ(read_num(s, 97, 1), 600);
  EXPECT_EQ(s.config_revision(), r0); // diagnostics are not configuration
  EXPECT_FALSE(s.ds_upload_requested());
  s.set_raw_internal(98, 2, 1000); // clamped to uint8
  EXPECT_EQ(s.raw(98, 2), 255);
  s.set_raw_internal(86, 0, 4096); // command 171: a local config change
  EXPECT_EQ(s.raw(86, 0), 4096);
  EXPECT_EQ(s.config_revision(), r0 + 1);
  EXPECT_TRUE(s.ds_upload_requested());
  const ParameterStore before = s;
  s.set_raw_internal(112, 0, 50); // volatile rows are not stored here
  s.set_raw_internal(999, 0, 1);
  EXPECT_TRUE(s == before);
}

} // namespace
} // namespace sreh
