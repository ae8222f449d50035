// A write that fails must say why and must never replace a good file. A full disk is
// simulated with /dev/full, whose writes fail with ENOSPC: the helper's test hook opens it in
// place of the temporary (a read-only folder does not stop root, who may run the tests).
#include "lituya/common/atomic_file.hpp"

#include <fcntl.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "lituya/common/vtu_writer.hpp"

namespace {

namespace fs = std::filesystem;

std::string contents(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

class AtomicFile : public ::testing::Test {
 protected:
  void SetUp() override {
    folder_ = fs::temp_directory_path() /
              ("lituya_atomic_file_test_" + std::to_string(::getpid()) + "_" +
               ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(folder_);
    fs::create_directories(folder_);
  }
  void TearDown() override { fs::remove_all(folder_); }

  // The original file a failed write must leave byte for byte.
  fs::path good_file(const std::string& name) {
    const fs::path file = folder_ / name;
    lituya::write_file_atomically(file, std::string("good\0content\n", 13));
    return file;
  }

  fs::path folder_;
};

// The temporary is /dev/full: every write to it fails with "No space left on device".
int open_dev_full(const fs::path&) {
  return ::open("/dev/full", O_WRONLY | O_CLOEXEC);
}

std::string write_error(const fs::path& file, const std::function<void(std::ostream&)>& write,
                        const lituya::detail::OpenTemporary& open) {
  try {
    lituya::detail::write_file_atomically(file, write, open);
  } catch (const lituya::WriteError& e) {
    return e.what();
  }
  return "";
}

TEST_F(AtomicFile, WritesAndReplacesWithoutLeavingTheTemporary) {
  const fs::path file = good_file("table.csv");
  EXPECT_EQ(contents(file), std::string("good\0content\n", 13));
  lituya::write_file_atomically(file, [](std::ostream& out) { out << "a,b\n1,2\n"; });
  EXPECT_EQ(contents(file), "a,b\n1,2\n");
  EXPECT_FALSE(fs::exists(lituya::temporary_file_for(file)));
}

TEST_F(AtomicFile, FullDiskNamesFileAndReasonAndKeepsTheGoodFile) {
  if (::access("/dev/full", W_OK) != 0) GTEST_SKIP() << "/dev/full is not available";
  const fs::path file = good_file("release_points.pvd");
  const std::string before = contents(file);
  // Small content stays in the buffer until the flush, which is where it fails.
  const std::string message = write_error(
      file, [](std::ostream& out) { out << "<VTKFile/>\n"; }, open_dev_full);
  EXPECT_NE(message.find("No space left on device"), std::string::npos) << message;
  EXPECT_NE(message.find(file.string()), std::string::npos) << message;
  EXPECT_EQ(contents(file), before);
  EXPECT_FALSE(fs::exists(lituya::temporary_file_for(file)));
}

TEST_F(AtomicFile, FullDiskDuringALargeStreamedWriteKeepsTheGoodFile) {
  if (::access("/dev/full", W_OK) != 0) GTEST_SKIP() << "/dev/full is not available";
  const fs::path file = good_file("release_points_0001.vtu");
  const std::string before = contents(file);
  // Larger than the buffer: it fails inside the writer's callback, not at the flush, and the
  // writer carries on (as a VTU writer would) before the failure is noticed.
  const std::string block(1 << 20, 'x');
  const std::string message = write_error(
      file,
      [&](std::ostream& out) {
        out << "head";
        out.write(block.data(), static_cast<std::streamsize>(block.size()));
        out << "tail";
      },
      open_dev_full);
  EXPECT_NE(message.find("No space left on device"), std::string::npos) << message;
  EXPECT_NE(message.find(file.string()), std::string::npos) << message;
  EXPECT_EQ(contents(file), before);
}

TEST_F(AtomicFile, ATemporaryThatCannotBeCreatedNamesTheReason) {
  const fs::path file = folder_ / "missing_folder" / "summary.toml";
  try {
    lituya::write_file_atomically(file, "x");
    FAIL() << "no error";
  } catch (const lituya::WriteError& e) {
    EXPECT_NE(std::string(e.what()).find("No such file or directory"), std::string::npos)
        << e.what();
    EXPECT_NE(std::string(e.what()).find(file.string()), std::string::npos) << e.what();
  }
}

TEST_F(AtomicFile, AWriterThatThrowsLeavesTheGoodFile) {
  const fs::path file = good_file("gauges.csv");
  const std::string before = contents(file);
  EXPECT_THROW(lituya::write_file_atomically(file,
                                             [](std::ostream& out) {
                                               out << "half a table";
                                               throw std::logic_error("bug");
                                             }),
               std::logic_error);
  EXPECT_EQ(contents(file), before);
  EXPECT_FALSE(fs::exists(lituya::temporary_file_for(file)));
}

// The PVD is rewritten at every output: a failed update must leave the previous collection,
// which ParaView still opens. The update is made to fail by a folder where its temporary goes
// (creating it fails with "Is a directory", also for root).
TEST_F(AtomicFile, PvdWriterWhoseUpdateFailsLeavesThePreviousPvd) {
  const fs::path file = folder_ / "release_points.pvd";
  lituya::PvdWriter pvd(file);
  pvd.add(0.0, "release_points_0000.vtu");
  const std::string before = contents(file);
  fs::create_directory(lituya::temporary_file_for(file));
  try {
    pvd.add(0.5, "release_points_0001.vtu");
    FAIL() << "no error";
  } catch (const lituya::WriteError& e) {
    EXPECT_NE(std::string(e.what()).find(file.string()), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("Is a directory"), std::string::npos) << e.what();
  }
  EXPECT_EQ(contents(file), before);
  // The failed entry is not kept: the next update lists what was written whole.
  fs::remove(lituya::temporary_file_for(file));
  pvd.add(1.0, "release_points_0002.vtu");
  const std::string after = contents(file);
  EXPECT_NE(after.find("release_points_0000.vtu"), std::string::npos);
  EXPECT_EQ(after.find("release_points_0001.vtu"), std::string::npos);
  EXPECT_NE(after.find("release_points_0002.vtu"), std::string::npos);
}

}  // namespace
