// Helpers shared by the language tests: reading the conformance suite.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace frep::test
{

/// Root of the conformance suite (FREPKIT_SHARED_DIR/hyperfun/conformance).
std::filesystem::path conformance_dir();

/// Whole file as bytes; empty string when it cannot be read.
std::string read_file(const std::filesystem::path& path);

struct ConformanceCase
{
  std::string category;
  std::string name;
  std::filesystem::path hf;       ///< the program
  std::filesystem::path expected; ///< what the original did
};

/// Every case listed in INDEX.tsv, in order.
std::vector<ConformanceCase> conformance_cases();

} // namespace frep::test
