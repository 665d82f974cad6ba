// A main() for the fuzz harnesses without libFuzzer: runs LLVMFuzzerTestOneInput once on every
// file named on the command line (folders: every regular file in them, sorted). The gcc build
// uses it to replay the seed corpora and the committed crash inputs as ordinary tests; the
// clang build links the same harness with -fsanitize=fuzzer instead.
#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <iterator>
#include <string>
#include <vector>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size);

namespace
{

std::vector<std::filesystem::path> input_files(const std::filesystem::path& argument)
{
  std::vector<std::filesystem::path> files;
  if (std::filesystem::is_directory(argument))
  {
    for (const auto& entry : std::filesystem::recursive_directory_iterator(argument))
    {
      if (entry.is_regular_file())
      {
        files.push_back(entry.path());
      }
    }
    std::sort(files.begin(), files.end());
  }
  else
  {
    files.push_back(argument);
  }
  return files;
}

} // namespace

int main(int argc, char** argv)
{
  std::size_t count = 0;
  for (int i = 1; i < argc; ++i)
  {
    if (!std::filesystem::exists(argv[i]))
    {
      std::cerr << "replay: no such file or folder: " << argv[i] << '\n';
      return 2;
    }
    for (const auto& file : input_files(argv[i]))
    {
      std::ifstream in(file, std::ios::binary);
      const std::vector<char> bytes{ std::istreambuf_iterator<char>(in),
        std::istreambuf_iterator<char>() };
      LLVMFuzzerTestOneInput(reinterpret_cast<const std::uint8_t*>(bytes.data()), bytes.size());
      ++count;
    }
  }
  // An empty corpus would make the test pass without running anything.
  if (count == 0)
  {
    std::cerr << "replay: no input files\n";
    return 2;
  }
  std::cout << "replay: " << count << " inputs, no oracle failed\n";
  return 0;
}
