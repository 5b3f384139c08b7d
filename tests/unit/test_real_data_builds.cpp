// Every real mesh of ../shared/data builds into a valid ARG (skipped when the data is absent).
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <sstream>

#include "common/parallel_for.hpp"
#include "graph/serialize.hpp"
#include "match/similarity.hpp"
#include "pipeline/build_arg.hpp"

namespace fs = std::filesystem;
using namespace arg;

namespace {

std::string slurp(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

// The texture an OBJ of the shared data set comes with, by its folder's convention.
std::string texture_for(const fs::path& mesh) {
  if (mesh.extension() != ".obj") return {};
  for (const char* suffix : {"_diffuse.tga", ".png"}) {
    fs::path t = mesh.parent_path() / (mesh.stem().string() + suffix);
    if (fs::exists(t)) return slurp(t);
  }
  return {};
}

}  // namespace

TEST(RealData, EveryMeshOfTheSharedDataBuildsAndMatchesItself) {
  const fs::path root = ARG_SHARED_DATA;
  if (!fs::exists(root)) GTEST_SKIP() << "no shared data at " << root << ": skipping";
  std::vector<fs::path> meshes;
  for (const auto& entry : fs::recursive_directory_iterator(root)) {
    const std::string ext = entry.path().extension().string();
    if (ext == ".off" || ext == ".obj" || ext == ".ply" || ext == ".stl" || ext == ".glb")
      meshes.push_back(entry.path());
  }
  std::sort(meshes.begin(), meshes.end());
  ASSERT_FALSE(meshes.empty());
#ifdef ARG_SANITIZED
  // Under the sanitizers (ten times slower: about 25 minutes for the whole sweep) every mesh of
  // a small folder (the museum's and textured formats) and every sixteenth of a large one (the
  // labelled sets: every eighth took four of make test's minutes); the release build sweeps
  // all of them.
  std::map<fs::path, std::vector<fs::path>> by_folder;
  for (const auto& m : meshes) by_folder[*fs::relative(m, root).begin()].push_back(m);
  std::vector<fs::path> sample;
  for (const auto& [folder, in_folder] : by_folder) {
    const std::size_t stride = in_folder.size() > 64 ? 16 : 1;
    for (std::size_t i = 0; i < in_folder.size(); i += stride) sample.push_back(in_folder[i]);
  }
  meshes.swap(sample);
#endif
  // Two builds at a time; each failure goes to its mesh's slot, so they are reported in order.
  std::vector<std::string> failures(meshes.size());
  parallel_for(meshes.size(), 2, [&](std::size_t i) {
    try {
      std::string bytes = build_arg_bytes(slurp(meshes[i]), texture_for(meshes[i]));
      ArgGraph g = deserialize_arg(bytes);
      if (arg_similarity(g, g) != 0.0) throw std::runtime_error("SIM(M, M) is not 0");
    } catch (const std::exception& e) {
      failures[i] = meshes[i].string() + ": " + e.what();
    }
  });
  failures.erase(std::remove(failures.begin(), failures.end(), std::string()), failures.end());
  for (const auto& f : failures) ADD_FAILURE() << f;
  RecordProperty("meshes", int(meshes.size()));
  std::cout << "built " << meshes.size() - failures.size() << " of " << meshes.size()
            << " meshes\n";
}
