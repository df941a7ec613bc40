#pragma once
// `rs4sim archive` run as a process on a real SQLite file in a temporary directory. The
// archive is filled through the library as the proxy will fill it: encode() of the set,
// its checksum(), and the report's summary_json().
//
//   version 1  default/4 #1  factory default, serial 1001, upload
//   version 2  default/4 #2  pair 2 protective segments 100..140 raised 1500 → 1850 mm
//   version 3  line2/5   #1  factory default with response time 160 ms, serial 2002
#include "rs4/report/parameter_summary.h"
#include "rs4/scanner/parameter_codec.h"
#include "storage/sqlite_archive.h"

#include <boost/property_tree/json_parser.hpp>
#include <boost/property_tree/ptree.hpp>
#include <boost/property_tree/xml_parser.hpp>
#include <gtest/gtest.h>

#include <sys/wait.h>
#include <unistd.h>

#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

namespace rs4sim::app::testing {

using boost::property_tree::ptree;

struct CliResult {
  int exit_code = -1;
  std::string out;
  std::string err;
};

inline std::string read_text(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

inline void write_text(const std::filesystem::path& path, const std::string& text) {
  std::ofstream(path, std::ios::binary) << text;
}

inline ptree parse_json(const std::string& text) {
  std::istringstream in(text);
  ptree tree;
  boost::property_tree::read_json(in, tree);
  return tree;
}

inline ptree parse_xml(const std::string& text) {
  std::istringstream in(text);
  ptree tree;
  boost::property_tree::read_xml(in, tree);
  return tree;
}

// The i-th element of a JSON array.
inline const ptree& at(const ptree& array, std::size_t i) {
  auto it = array.begin();
  std::advance(it, static_cast<std::ptrdiff_t>(i));
  return it->second;
}

inline rs4::scanner::ParameterSet raised_pair2() {
  auto set = rs4::scanner::factory_default();
  for (std::size_t n = 100; n <= 140; ++n) set.pairs[1].protective_mm[n] = 1850;
  return set;
}

class ArchiveCli : public ::testing::Test {
 protected:
  void SetUp() override {
    std::string pattern = (std::filesystem::temp_directory_path() / "rs4sim-cli-XXXXXX");
    ASSERT_NE(::mkdtemp(pattern.data()), nullptr);
    dir_ = pattern;
    archive_ = dir_ / "archive.sqlite3";
    auto a = storage::SqliteArchive::open(archive_).value();
    auto late = rs4::scanner::factory_default();
    late.response_steps = 2;
    store(*a, {"default", 4}, rs4::scanner::factory_default(), "1001", 1'764'590'400'000);
    store(*a, {"default", 4}, raised_pair2(), "1001", 1'764'594'000'000);
    store(*a, {"line2", 5}, late, "2002", 1'764'597'600'000);
    storage::SyncLogEntry entry;
    entry.station = {"default", 4};
    entry.at = storage::Timestamp{std::chrono::milliseconds{1'764'594'000'500}};
    entry.reason = "parameter change";
    entry.direction = storage::SyncDirection::kUpload;
    entry.duration = std::chrono::milliseconds{1500};
    ASSERT_TRUE(a->log_sync(entry));
  }
  void TearDown() override {
    std::error_code ec;
    std::filesystem::remove_all(dir_, ec);
  }

  static void store(storage::ParameterArchive& a, storage::StationKey key,
                    const rs4::scanner::ParameterSet& set, const std::string& serial,
                    std::int64_t at_ms) {
    auto with_serial = set;  // a set read from the device carries its serial number
    with_serial.identity.serial_number = static_cast<std::uint32_t>(std::stoul(serial));
    const auto blob = rs4::scanner::encode(with_serial);
    storage::StoreRequest r;
    r.station = std::move(key);
    r.device_type = "0x0004";  // as the proxy records it (rs4/scanner/identity_text.h)
    r.serial_number = serial;
    r.blob = blob;
    r.crc32 = rs4::scanner::checksum(with_serial);
    r.summary = rs4::report::summary_json(with_serial);
    r.at = storage::Timestamp{std::chrono::milliseconds{at_ms}};
    ASSERT_TRUE(a.store(r));
  }

  // rs4sim archive <args> --archive <the file unless `archive` says otherwise>.
  CliResult run(const std::string& args, const std::string& archive = "") const {
    return run_rs4sim("archive " + args + " --archive '" +
                      (archive.empty() ? archive_.string() : archive) + "'");
  }

  // `rs4sim archive <args>` fails with `exit_code` and says `words` on stderr; its result.
  CliResult expect_refusal(const std::string& args, int exit_code, const std::string& words) const {
    auto r = run(args);
    EXPECT_EQ(r.exit_code, exit_code) << args;
    EXPECT_NE(r.err.find(words), std::string::npos) << r.err;
    return r;
  }

  // rs4sim <args>, stdout and stderr captured.
  CliResult run_rs4sim(const std::string& args) const {
    const auto err = dir_ / "stderr.txt";
    const std::string command = std::string(RS4SIM_EXE) + " " + args + " 2>'" + err.string() + "'";
    CliResult r;
    FILE* pipe = ::popen(command.c_str(), "r");
    if (pipe == nullptr) return r;
    std::array<char, 4096> buffer{};
    std::size_t n = 0;
    while ((n = std::fread(buffer.data(), 1, buffer.size(), pipe)) > 0)
      r.out.append(buffer.data(), n);
    const int status = ::pclose(pipe);
    r.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    r.err = read_text(err);
    return r;
  }

  // Everything a reader can see of the archive, to prove it unchanged.
  std::string contents() const {
    return run("list --json").out + run("history --address 4 --json").out +
           run("history --bus line2 --address 5 --json").out;
  }

  std::filesystem::path dir_;
  std::filesystem::path archive_;
};

}  // namespace rs4sim::app::testing
