// A fresh directory per test for the durable-output tests.
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <string>
#include <vector>

namespace frep::durable::testing
{

/// FREP_DURABLE_TEST_OUTPUT_DIR/<suite>.<test>, emptied and created.
inline std::filesystem::path fresh_directory()
{
  const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
  const std::filesystem::path directory = std::filesystem::path(FREP_DURABLE_TEST_OUTPUT_DIR) /
                                          (std::string(info->test_suite_name()) + "." + info->name());
  std::filesystem::remove_all(directory);
  std::filesystem::create_directories(directory);
  return directory;
}

/// The names of the files in `directory`, sorted.
inline std::vector<std::string> names_in(const std::filesystem::path& directory)
{
  std::vector<std::string> names;
  for (const auto& entry : std::filesystem::directory_iterator(directory))
    names.push_back(entry.path().filename().string());
  std::sort(names.begin(), names.end());
  return names;
}

} // namespace frep::durable::testing
