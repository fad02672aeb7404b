// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (c) 2026 The FeatureRecon authors.
// Scratch files for the I/O tests: private to the running test and process, removed when the test ends.
#ifndef FEATURERECON_TEST_IO_SCRATCH_FILE_H
#define FEATURERECON_TEST_IO_SCRATCH_FILE_H

#include <gtest/gtest.h>

#include <cstdio>
#include <string>
#include <vector>

#include <unistd.h>

namespace FeatureRecon {
namespace test {

/// Removes, when a test ends, every scratch file that scratch_path() handed out during it (whether the test
/// wrote it or not), so that repeated runs leave nothing in ::testing::TempDir().
class Scratch_file_remover : public ::testing::EmptyTestEventListener {
 public:
  static Scratch_file_remover& instance() {
    static Scratch_file_remover* remover = [] {
      auto* r = new Scratch_file_remover;  // owned by gtest's listener list from here on
      ::testing::UnitTest::GetInstance()->listeners().Append(r);
      return r;
    }();
    return *remover;
  }
  void add(const std::string& path) { paths_.push_back(path); }
  const std::vector<std::string>& pending() const { return paths_; }
  void OnTestEnd(const ::testing::TestInfo&) override {
    for (const std::string& p : paths_) std::remove(p.c_str());
    paths_.clear();
  }

 private:
  std::vector<std::string> paths_;
};

/// A path in ::testing::TempDir() private to this test and process (tests run in parallel processes sharing
/// the directory), removed when the test ends.
inline std::string scratch_path(const std::string& name) {
  const ::testing::TestInfo* t = ::testing::UnitTest::GetInstance()->current_test_info();
  const std::string path = ::testing::TempDir() + "/featurerecon_" + t->test_suite_name() + "_" + t->name() +
                           "_" + std::to_string(::getpid()) + "_" + name;
  Scratch_file_remover::instance().add(path);
  return path;
}

}  // namespace test
}  // namespace FeatureRecon

#endif  // FEATURERECON_TEST_IO_SCRATCH_FILE_H
