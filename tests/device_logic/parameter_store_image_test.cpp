// ParameterStore: the non-volatile image (power cycles keep the
// configuration, manual 6.2) and Data Storage / device exchange (manual 8).
#include <gtest/gtest.h>

#include <cstdint>
#include <string>
#include <vector>

#include "device_logic/parameter_store.hpp"
#include "device_logic/parameter_table.hpp"
#include "parameter_store_helpers.hpp"

namespace sreh {
namespace {

using namespace store_test;

// --------------------------------------------------------------- NVM image

ParameterStore modified_store() {
  ParameterStore s;
  EXPECT_EQ(put(s, 64, 1, 4321), kIsduOk);
  EXPECT_EQ(put(s, 81, 1, -65536), kIsduOk);
  EXPECT_EQ(put(s, 86, 0, -131072), kIsduOk);
  EXPECT_EQ(s.write(25, 0, str("function")).error, kIsduOk);
  s.set_raw_internal(97, 3, 123456);
  s.set_raw_internal(99, 2, 140);
  s.request_ds_upload();
  return s;
}

// Rewrites the trailing CRC so that only the deliberate corruption is tested.
Bytes with_fixed_crc(const Bytes& image) {
  Bytes out(image.begin(), image.end() - 4);
  const uint32_t c = crc32(out);
  for (int shift = 24; shift >= 0; shift -= 8) out.push_back(static_cast<uint8_t>(c >> shift));
  return out;
}

TEST(ParameterStoreImage, RoundTrip) {
  const ParameterStore s = modified_store();
  const Bytes image = s.image();
  const auto back = ParameterStore::from_image(image);
  ASSERT_TRUE(back.has_value());
  EXPECT_TRUE(*back == s);
  EXPECT_EQ(back->image(), image);
  EXPECT_EQ(back->parameter_checksum(), s.parameter_checksum());
  EXPECT_TRUE(back->ds_upload_requested());
  const auto fresh = ParameterStore::from_image(ParameterStore{}.image());
  ASSERT_TRUE(fresh.has_value());
  EXPECT_TRUE(*fresh == ParameterStore{});
}

// Power cycle during an open download: the buffer is not non-volatile.
TEST(ParameterStoreImage, OpenDownloadIsNotPersisted) {
  ParameterStore s;
  ASSERT_EQ(cmd(s, kCmdParamDownloadStart), kIsduOk);
  ASSERT_EQ(put(s, 82, 0, 1), kIsduOk);
  const auto back = ParameterStore::from_image(s.image());
  ASSERT_TRUE(back.has_value());
  EXPECT_FALSE(back->download_open());
  EXPECT_TRUE(*back == ParameterStore{});
}

TEST(ParameterStoreImage, CorruptImagesRefused) {
  const Bytes good = modified_store().image();
  EXPECT_FALSE(ParameterStore::from_image(Bytes{}).has_value());
  EXPECT_FALSE(ParameterStore::from_image(Bytes(good.begin(), good.begin() + 10)).has_value());
  EXPECT_FALSE(ParameterStore::from_image(Bytes(good.begin(), good.end() - 1)).has_value());
  for (std::size_t i = 0; i < good.size(); ++i) { // every single flipped bit is caught
    Bytes bad = good;
    bad[i] ^= 0x10;
    EXPECT_FALSE(ParameterStore::from_image(bad).has_value()) << "octet " << i;
  }
}

TEST(ParameterStoreImage, IncompatibleContentRefusedEvenWithValidCrc) {
  const Bytes good = ParameterStore{}.image();
  const std::size_t header = 9; // magic 4, version 2, flags 1, count 2
  auto find_entry = [&](uint16_t index, uint8_t sub) {
    std::size_t at = header;
    while (at + 4 <= good.size() - 4) {
      if (((good[at] << 8) | good[at + 1]) == index && good[at + 2] == sub) return at;
      at += 4 + good[at + 3];
    }
    ADD_FAILURE() << "entry not found";
    return at;
  };
  {
    Bytes bad = good;
    bad[5] = 2; // version 2
    EXPECT_FALSE(ParameterStore::from_image(with_fixed_crc(bad)).has_value());
  }
  {
    Bytes bad = good;
    bad[6] = 0x02; // unknown flag
    EXPECT_FALSE(ParameterStore::from_image(with_fixed_crc(bad)).has_value());
  }
  {
    Bytes bad = good; // speed 0: below the manual's range
    const std::size_t at = find_entry(64, 1);
    bad[at + 4] = 0;
    bad[at + 5] = 0;
    EXPECT_FALSE(ParameterStore::from_image(with_fixed_crc(bad)).has_value());
  }
  {
    Bytes bad = good; // 81.1 = 0x7FFF0000 > 81.2: inconsistent
    const std::size_t at = find_entry(81, 1);
    bad[at + 4] = 0x7F;
    bad[at + 5] = 0xFF;
    EXPECT_FALSE(ParameterStore::from_image(with_fixed_crc(bad)).has_value());
  }
  {
    Bytes bad = good; // entry renamed to a volatile row (112)
    const std::size_t at = find_entry(82, 0);
    bad[at + 1] = 112;
    EXPECT_FALSE(ParameterStore::from_image(with_fixed_crc(bad)).has_value());
  }
  {
    Bytes bad = good; // duplicate entry: 83 renamed to 82
    const std::size_t at = find_entry(83, 0);
    bad[at + 1] = 82;
    EXPECT_FALSE(ParameterStore::from_image(with_fixed_crc(bad)).has_value());
  }
  {
    Bytes bad = good; // wrong length for a uint16 row
    const std::size_t at = find_entry(64, 1);
    bad[at + 3] = 1;
    EXPECT_FALSE(ParameterStore::from_image(with_fixed_crc(bad)).has_value());
  }
}

// ------------------------------------------------- Data Storage (manual 8)

TEST(DataStorageIndex3, SizeChecksumAndList) {
  ParameterStore s;
  const auto list = decode_index_list(s.read(3, 5).data);
  ASSERT_TRUE(list.has_value());
  EXPECT_EQ(*list, std::vector<DsEntry>(data_storage_entries().begin(), data_storage_entries().end()));
  uint32_t size = 0;
  for (const auto& e : *list) size += 4 + static_cast<uint32_t>(s.read(e.index, e.subindex).data.size());
  EXPECT_EQ(read_num(s, 3, 3), size);
  EXPECT_EQ(read_num(s, 3, 4), s.parameter_checksum());
  const uint32_t c0 = s.parameter_checksum();
  ASSERT_EQ(put(s, 71, 5, 1), kIsduOk);
  EXPECT_NE(s.parameter_checksum(), c0);
  ASSERT_EQ(put(s, 71, 5, 146), kIsduOk);
  EXPECT_EQ(s.parameter_checksum(), c0);
  s.set_raw_internal(96, 0, 9); // diagnostics are not in the DS set
  EXPECT_EQ(s.parameter_checksum(), c0);
}

TEST(DataStorageIndex3, StatePropertyFollowsCommands) {
  ParameterStore s;
  EXPECT_EQ(read_num(s, 3, 2), 0);
  ASSERT_EQ(ds(s, DsCommand::UploadStart), kIsduOk);
  EXPECT_EQ(read_num(s, 3, 2), 0x02);
  s.request_ds_upload();
  EXPECT_EQ(read_num(s, 3, 2), 0x82);
  ASSERT_EQ(ds(s, DsCommand::UploadEnd), kIsduOk); // the master holds the set: flag cleared
  EXPECT_EQ(read_num(s, 3, 2), 0);
  ASSERT_EQ(ds(s, DsCommand::DownloadStart), kIsduOk);
  EXPECT_EQ(read_num(s, 3, 2), 0x04);
  EXPECT_TRUE(s.download_open());
  ASSERT_EQ(put(s, 82, 0, 1), kIsduOk);
  ASSERT_EQ(ds(s, DsCommand::Break), kIsduOk);
  EXPECT_EQ(read_num(s, 3, 2), 0);
  EXPECT_FALSE(s.download_open());
  EXPECT_EQ(s.raw(82, 0), 0);
}

// Manual 8 device exchange: a master backs up the DS set of the installed
// module and restores it into a factory-new replacement.
TEST(DataStorageIndex3, ReplacementDeviceGetsIdenticalConfiguration) {
  ParameterStore old_device;
  for (int n = 0; n < 8; ++n) {
    const auto i = static_cast<uint16_t>(64 + n);
    ASSERT_EQ(put(old_device, i, 1, 1000 + 100 * n), kIsduOk);
    ASSERT_EQ(put(old_device, i, 4, 500 * n), kIsduOk);
    ASSERT_EQ(put(old_device, i, 7, 2000 + n), kIsduOk);
  }
  ASSERT_EQ(put(old_device, 81, 2, 3 * 65536), kIsduOk);
  ASSERT_EQ(put(old_device, 81, 1, -65536), kIsduOk);
  ASSERT_EQ(put(old_device, 81, 3, 1), kIsduOk);
  ASSERT_EQ(put(old_device, 82, 0, 1), kIsduOk);
  ASSERT_EQ(put(old_device, 83, 0, 2), kIsduOk);
  ASSERT_EQ(put(old_device, 85, 1, 20000), kIsduOk);
  ASSERT_EQ(put(old_device, 86, 0, 12345), kIsduOk);
  ASSERT_EQ(put(old_device, 87, 1, 25), kIsduOk);
  ASSERT_EQ(old_device.write(24, 0, str("press line 3")).error, kIsduOk);
  ASSERT_EQ(old_device.write(26, 0, str("hall B")).error, kIsduOk);

  // Master upload: DS UploadStart, read the index list and every entry, UploadEnd.
  struct Saved { DsEntry entry; Bytes data; };
  std::vector<Saved> backup;
  ASSERT_EQ(ds(old_device, DsCommand::UploadStart), kIsduOk);
  const auto list = decode_index_list(old_device.read(3, 5).data);
  ASSERT_TRUE(list.has_value());
  for (const auto& e : *list) {
    const IsduResult r = old_device.read(e.index, e.subindex);
    ASSERT_TRUE(r.ok()) << e.index;
    backup.push_back({e, r.data});
  }
  const auto saved_checksum = static_cast<uint32_t>(read_num(old_device, 3, 4));
  ASSERT_EQ(ds(old_device, DsCommand::UploadEnd), kIsduOk);

  // Replacement: factory-new; checksum differs, so the master downloads.
  ParameterStore replacement;
  ASSERT_NE(static_cast<uint32_t>(read_num(replacement, 3, 4)), saved_checksum);
  ASSERT_EQ(ds(replacement, DsCommand::DownloadStart), kIsduOk);
  for (const auto& saved : backup)
    ASSERT_EQ(replacement.write(saved.entry.index, saved.entry.subindex, saved.data).error, kIsduOk)
        << saved.entry.index;
  ASSERT_EQ(ds(replacement, DsCommand::DownloadEnd), kIsduOk);

  EXPECT_TRUE(replacement.same_configuration(old_device));
  EXPECT_EQ(static_cast<uint32_t>(read_num(replacement, 3, 4)), saved_checksum);
  EXPECT_EQ(replacement.tag(24), "press line 3");
  EXPECT_EQ(replacement.raw(81, 1), -65536);
  EXPECT_EQ(read_num(replacement, 3, 2), 0); // inactive, no upload request
  for (int n = 0; n < 8; ++n) {
    const MotionParameterSet a = old_device.motion_set(n);
    const MotionParameterSet b = replacement.motion_set(n);
    EXPECT_EQ(a.speed_dps, b.speed_dps);
    EXPECT_EQ(a.load_gcm2, b.load_gcm2);
    EXPECT_EQ(a.settling_timeout_ms, b.settling_timeout_ms);
  }
}

} // namespace
} // namespace sreh
