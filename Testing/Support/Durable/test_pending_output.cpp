// PendingFile and AtomicOutput: the target appears only complete, the temporary never outlives
// its owner, and nothing is put in place after a signal under an InterruptGuard.
#include "Durable/atomic_output.h"
#include "Durable/interrupt_guard.h"
#include "Durable/pending_file.h"

#include "durable_test_support.h"

#include <gtest/gtest.h>

#include <csignal>
#include <fstream>
#include <iterator>

namespace
{

namespace fs = std::filesystem;
using frep::durable::testing::fresh_directory;
using frep::durable::testing::names_in;

std::string read_text(const fs::path& path)
{
  std::ifstream in(path, std::ios::binary);
  return { std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>() };
}

TEST(PendingFile, TheTemporaryLiesBesideTheTargetAndBecomesIt)
{
  const fs::path dir = fresh_directory();
  frep::durable::PendingFile file(dir / "out.wav");
  ASSERT_EQ(file.error(), "");
  EXPECT_EQ(file.temporary().parent_path(), dir);
  EXPECT_NE(file.temporary().filename().string().find("out.wav.tmp-"), std::string::npos);
  EXPECT_TRUE(fs::exists(file.temporary())); // created, so the name is ours
  EXPECT_FALSE(fs::exists(dir / "out.wav"));
  std::ofstream(file.temporary(), std::ios::binary) << "RIFF";
  EXPECT_EQ(file.commit(), "");
  EXPECT_TRUE(file.committed());
  EXPECT_EQ(read_text(dir / "out.wav"), "RIFF");
  EXPECT_EQ(names_in(dir), std::vector<std::string>{ "out.wav" });
}

TEST(PendingFile, TwoPendingFilesOfOneTargetHaveTwoTemporaries)
{
  const fs::path dir = fresh_directory();
  const frep::durable::PendingFile a(dir / "x.txt");
  const frep::durable::PendingFile b(dir / "x.txt");
  ASSERT_EQ(a.error(), "");
  ASSERT_EQ(b.error(), "");
  EXPECT_NE(a.temporary(), b.temporary());
}

TEST(PendingFile, AnUncommittedFileLeavesNothingAndKeepsTheOldTarget)
{
  const fs::path dir = fresh_directory();
  std::ofstream(dir / "keep.txt") << "old";
  {
    frep::durable::PendingFile file(dir / "keep.txt");
    std::ofstream(file.temporary()) << "half-writ";
  } // an early return: the writer failed
  EXPECT_EQ(read_text(dir / "keep.txt"), "old");
  EXPECT_EQ(names_in(dir), std::vector<std::string>{ "keep.txt" });
}

TEST(PendingFile, AnUnwritableDirectoryIsSaidAndCommitFails)
{
  const fs::path dir = fresh_directory();
  frep::durable::PendingFile file(dir / "no-such-dir" / "out.txt");
  EXPECT_NE(file.error().find("cannot create the temporary file"), std::string::npos)
    << file.error();
  EXPECT_TRUE(file.temporary().empty());
  EXPECT_NE(file.commit(), "");
}

TEST(AtomicOutput, CommitPutsTheStreamInPlace)
{
  const fs::path dir = fresh_directory();
  {
    frep::durable::AtomicOutput out((dir / "mesh.stl").string());
    out.stream() << "solid x\n";
    EXPECT_EQ(names_in(dir).size(), 1u);
    EXPECT_FALSE(fs::exists(dir / "mesh.stl")); // only the temporary so far
    out.commit();
  }
  EXPECT_EQ(read_text(dir / "mesh.stl"), "solid x\n");
  EXPECT_EQ(names_in(dir), std::vector<std::string>{ "mesh.stl" });
}

TEST(AtomicOutput, AnUnwritablePathThrowsOutputError)
{
  const fs::path dir = fresh_directory();
  EXPECT_THROW(frep::durable::AtomicOutput((dir / "missing" / "a.txt").string()),
    frep::durable::OutputError);
}

TEST(AtomicOutput, NothingIsPutInPlaceAfterASignal)
{
  const fs::path dir = fresh_directory();
  std::ofstream(dir / "frame.png") << "old";
  {
    frep::durable::InterruptGuard guard;
    frep::durable::AtomicOutput out((dir / "frame.png").string());
    out.stream() << "new";
    std::raise(SIGTERM); // the guard's handler records it; the process goes on
    EXPECT_TRUE(frep::durable::InterruptGuard::interrupted());
    EXPECT_EQ(frep::durable::InterruptGuard::signal_number(), SIGTERM);
    EXPECT_THROW(out.commit(), frep::durable::Interrupted);
  }
  EXPECT_EQ(read_text(dir / "frame.png"), "old");
  EXPECT_EQ(names_in(dir), std::vector<std::string>{ "frame.png" });
  // The next guard starts clean (the flag is process-wide; the other tests need it down).
  const frep::durable::InterruptGuard next;
  EXPECT_FALSE(frep::durable::InterruptGuard::interrupted());
}

} // namespace
