// Every input the fuzzers ever crashed on (tests/fuzz/regressions/<target>/) is replayed through
// the same entry point: it must end in a result or an arg::Error, never a crash or another error.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iterator>
#include <string>
#include <vector>

#define ARG_FUZZ_NO_MAIN
#include "../fuzz/fuzz_arg_binary.cpp"
#include "../fuzz/fuzz_arg_structure.cpp"
#include "../fuzz/fuzz_arg_text.cpp"
#include "../fuzz/fuzz_build.cpp"
#include "../fuzz/fuzz_build_options.cpp"
#include "../fuzz/fuzz_decode_image.cpp"
#include "../fuzz/fuzz_ivf_page.cpp"
#include "../fuzz/fuzz_read_glb.cpp"
#include "../fuzz/fuzz_read_obj.cpp"
#include "../fuzz/fuzz_read_off.cpp"
#include "../fuzz/fuzz_read_ply.cpp"
#include "../fuzz/fuzz_read_stl.cpp"
#include "../fuzz/fuzz_sketch.cpp"
#include "../fuzz/fuzz_weights.cpp"

namespace {

namespace fs = std::filesystem;
using Entry = std::function<int(const std::uint8_t*, std::size_t)>;

struct Target {
  const char* name;
  Entry entry;
};

const std::vector<Target>& targets() {
  using namespace arg::fuzz;
  static const std::vector<Target> all = {
      {"fuzz_arg_binary", fuzz_arg_binary},
      {"fuzz_arg_structure", fuzz_arg_structure},
      {"fuzz_arg_text", fuzz_arg_text},
      {"fuzz_build", fuzz_build},
      {"fuzz_build_options", fuzz_build_options},
      {"fuzz_decode_image", fuzz_decode_image},
      {"fuzz_ivf_page", fuzz_ivf_page},
      {"fuzz_read_glb", fuzz_read_glb},
      {"fuzz_read_obj", fuzz_read_obj},
      {"fuzz_read_off", fuzz_read_off},
      {"fuzz_read_ply", fuzz_read_ply},
      {"fuzz_read_stl", fuzz_read_stl},
      {"fuzz_sketch", fuzz_sketch},
      {"fuzz_weights", fuzz_weights},
  };
  return all;
}

// tests/fuzz/regressions, found from this file's own path so the test runs from any directory.
fs::path regressions_dir() {
  return fs::path(__FILE__).parent_path().parent_path() / "fuzz" / "regressions";
}

std::string read_bytes(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

// Replays every file of `folder` through `target`; returns how many there were.
std::size_t replay_folder(const Target& target, const fs::path& folder) {
  if (!fs::is_directory(folder)) return 0;
  std::vector<fs::path> files;
  for (const auto& item : fs::directory_iterator(folder))
    if (item.is_regular_file()) files.push_back(item.path());
  std::sort(files.begin(), files.end());
  for (const fs::path& file : files) {
    const std::string bytes = read_bytes(file);
    // The entry point swallows arg::Error; anything else escaping it is a failure.
    EXPECT_NO_THROW(target.entry(reinterpret_cast<const std::uint8_t*>(bytes.data()), bytes.size()))
        << target.name << "/" << file.filename().string();
  }
  return files.size();
}

TEST(FuzzRegressions, EveryInputAFuzzerCrashedOnEndsInAResultOrAnArgError) {
  ASSERT_TRUE(fs::is_directory(regressions_dir())) << regressions_dir();
  std::size_t replayed = 0;
  for (const Target& target : targets())
    replayed += replay_folder(target, regressions_dir() / target.name);
  EXPECT_GT(replayed, 0u);
}

TEST(FuzzRegressions, SeedCorporaAreReplayedToo) {
  // The committed seeds hold the hand-written edge cases (huge counts, NaN, truncated images...):
  // replaying them keeps those cases covered in every unit test run, fuzzer or not.
  const fs::path corpus = regressions_dir().parent_path() / "corpus";
  ASSERT_TRUE(fs::is_directory(corpus)) << corpus;
  std::size_t replayed = 0;
  for (const Target& target : targets()) replayed += replay_folder(target, corpus / target.name);
  EXPECT_GT(replayed, 100u);
}

}  // namespace
