// durable_rename puts a finished temporary in place, or says what failed and leaves things as
// they were. (That the fsyncs reach the disk is not observable here; that they are called on the
// file and its directory is what the function is.)
#include "Durable/durable_file.h"

#include "durable_test_support.h"

#include <gtest/gtest.h>

#include <fstream>
#include <iterator>

namespace
{

namespace fs = std::filesystem;

void write_text(const fs::path& path, const std::string& text)
{
  std::ofstream(path, std::ios::binary) << text;
}

std::string read_text(const fs::path& path)
{
  std::ifstream in(path, std::ios::binary);
  return { std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>() };
}

TEST(DurableFile, RenamesOverTheTargetKeepingTheContent)
{
  const fs::path dir = frep::durable::testing::fresh_directory();
  write_text(dir / "out.txt", "old");
  write_text(dir / "out.txt.tmp", "new content");
  EXPECT_EQ(frep::durable::durable_rename(dir / "out.txt.tmp", dir / "out.txt"), "");
  EXPECT_EQ(read_text(dir / "out.txt"), "new content");
  EXPECT_FALSE(fs::exists(dir / "out.txt.tmp"));
  EXPECT_EQ(frep::durable::testing::names_in(dir), std::vector<std::string>{ "out.txt" });
}

TEST(DurableFile, AMissingTemporaryIsAnErrorAndTheTargetStays)
{
  const fs::path dir = frep::durable::testing::fresh_directory();
  write_text(dir / "out.txt", "old");
  const std::string problem = frep::durable::durable_rename(dir / "gone.tmp", dir / "out.txt");
  EXPECT_NE(problem.find("gone.tmp"), std::string::npos) << problem;
  EXPECT_EQ(read_text(dir / "out.txt"), "old");
}

TEST(DurableFile, AnImpossibleRenameIsAnErrorAndTheTemporaryStays)
{
  const fs::path dir = frep::durable::testing::fresh_directory();
  write_text(dir / "out.tmp", "data");
  const std::string problem =
    frep::durable::durable_rename(dir / "out.tmp", dir / "no-such-dir" / "out.txt");
  EXPECT_NE(problem.find("cannot rename"), std::string::npos) << problem;
  EXPECT_EQ(read_text(dir / "out.tmp"), "data");
}

TEST(DurableFile, SyncingAMissingDirectoryIsAnError)
{
  const fs::path dir = frep::durable::testing::fresh_directory();
  EXPECT_EQ(frep::durable::sync_directory(dir), "");
  EXPECT_NE(frep::durable::sync_directory(dir / "missing"), "");
  EXPECT_EQ(frep::durable::sync_directory(""), ""); // the current directory
}

} // namespace
