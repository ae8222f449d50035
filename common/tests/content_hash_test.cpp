// The fingerprint of the case files: the published FNV-1a 64 values, stable for the same
// files, independent of the order they are listed in, and changed by any edit or rename.
#include "lituya/common/content_hash.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <stdexcept>

namespace {

namespace fs = std::filesystem;

TEST(ContentHash, MatchesPublishedFnv1a64Values) {
  // Test vectors of the FNV reference (Fowler, Noll, Vo): "", "a", "foobar".
  EXPECT_EQ(lituya::fnv1a64(""), 0xcbf29ce484222325ull);
  EXPECT_EQ(lituya::fnv1a64("a"), 0xaf63dc4c8601ec8cull);
  EXPECT_EQ(lituya::fnv1a64("foobar"), 0x85944171f73967e8ull);
}

TEST(ContentHash, AddingInPiecesEqualsAddingAtOnce) {
  lituya::Fnv1a64 h;
  h.add("foo");
  h.add("bar");
  EXPECT_EQ(h.value(), lituya::fnv1a64("foobar"));
}

class CaseFiles : public ::testing::Test {
 protected:
  void SetUp() override {
    folder_ = fs::temp_directory_path() /
              ("lituya_hash_" +
               std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()));
    fs::remove_all(folder_);
    fs::create_directories(folder_ / "sub");
    write("stages.toml", "format = \"lituya-stages\"\n");
    write("points.vtu", "<VTKFile/>\n");
    write("sub/materials.toml", "[[material]]\n");
  }
  void TearDown() override { fs::remove_all(folder_); }
  void write(const fs::path& name, const std::string& text) {
    std::ofstream(folder_ / name, std::ios::binary) << text;
  }
  std::string hash() const {
    return lituya::hash_files(folder_, {"stages.toml", "points.vtu", "sub/materials.toml"});
  }
  fs::path folder_;
};

TEST_F(CaseFiles, StableAndIndependentOfListOrder) {
  const std::string first = hash();
  EXPECT_EQ(first.rfind("fnv1a64:", 0), 0u) << first;
  EXPECT_EQ(first.size(), 8u + 16u) << first;
  EXPECT_EQ(hash(), first);
  EXPECT_EQ(lituya::hash_files(folder_, {"sub/materials.toml", "points.vtu", "stages.toml"}),
            first);
  // The folder's own path is not part of it: a copied case has the same hash.
  const fs::path copy = folder_.string() + "_copy";
  fs::remove_all(copy);
  fs::copy(folder_, copy, fs::copy_options::recursive);
  EXPECT_EQ(lituya::hash_files(copy, {"stages.toml", "points.vtu", "sub/materials.toml"}), first);
  fs::remove_all(copy);
}

TEST_F(CaseFiles, ChangesWhenAFileChanges) {
  const std::string before = hash();
  write("points.vtu", "<VTKFile />\n");  // one byte more
  EXPECT_NE(hash(), before);
  write("points.vtu", "<VTKFile/>\n");
  EXPECT_EQ(hash(), before);
  write("points.vtu", "<VTKFile/>\r");  // same size, one byte different
  EXPECT_NE(hash(), before);
}

TEST_F(CaseFiles, MovingBytesBetweenFilesChangesIt) {
  // The concatenated bytes stay the same; the sizes in the hash tell the files apart.
  write("a", "xy");
  write("b", "z");
  const std::string before = lituya::hash_files(folder_, {"a", "b"});
  write("a", "x");
  write("b", "yz");
  EXPECT_NE(lituya::hash_files(folder_, {"a", "b"}), before);
}

TEST_F(CaseFiles, FolderHashCoversEveryFileAndNotesNewOnes) {
  const std::string before = lituya::hash_folder(folder_);
  EXPECT_EQ(lituya::hash_folder(folder_), hash());
  write("sub/extra.txt", "");
  EXPECT_NE(lituya::hash_folder(folder_), before);
}

TEST_F(CaseFiles, MissingFileNamesIt) {
  try {
    lituya::hash_files(folder_, {"stages.toml", "geometry.vtu"});
    FAIL() << "no error for a missing file";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("geometry.vtu"), std::string::npos) << e.what();
  }
}

}  // namespace
