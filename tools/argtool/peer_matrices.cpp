// Reading the peers' gzipped distance matrices into the form argtool eval --matrix writes.
#include "peer_matrices.hpp"

#include <zlib.h>

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <memory>
#include <stdexcept>

#include "common/errors.hpp"

namespace fs = std::filesystem;

namespace argtool {

namespace {

// The whole file, gunzipped (zlib reads a file that is not gzipped as it is).
std::string read_gzip_file(const std::string& path) {
  std::unique_ptr<gzFile_s, int (*)(gzFile)> in(gzopen(path.c_str(), "rb"), gzclose);
  if (!in) throw std::runtime_error("cannot open " + path);
  std::string out;
  char buf[1 << 16];
  int got;
  while ((got = gzread(in.get(), buf, sizeof buf)) > 0) out.append(buf, std::size_t(got));
  if (got < 0) throw std::runtime_error("cannot read " + path + ": not a gzip file?");
  return out;
}

// One space between numbers and no blank lines: the strict form parse_distance_matrix reads
// (the peers' files promise only whitespace).
std::string single_spaced(const std::string& text) {
  std::string out, line;
  auto flush = [&] {
    if (!line.empty()) out += line + '\n';
    line.clear();
  };
  bool gap = false;
  for (char c : text) {
    if (c == '\n') {
      flush();
      gap = false;
    } else if (std::isspace(static_cast<unsigned char>(c))) {
      gap = !line.empty();
    } else {
      if (gap) line += ' ';
      gap = false;
      line += c;
    }
  }
  flush();
  return out;
}

}  // namespace

std::vector<PeerMatrix> read_peer_matrices(const std::string& dir, const std::string& set,
                                           std::size_t models) {
  std::vector<PeerMatrix> peers;
  const fs::path folder = fs::path(dir) / set;
  if (!fs::is_directory(folder)) return peers;
  for (const auto& entry : fs::directory_iterator(folder)) {
    const std::string file = entry.path().filename().string();
    const std::size_t dot = file.find(".dist.txt");
    if (dot == std::string::npos || dot == 0) continue;
    const std::string tail = file.substr(dot);
    if (tail != ".dist.txt" && tail != ".dist.txt.gz") continue;
    PeerMatrix peer{file.substr(0, dot), {}};
    try {
      peer.matrix =
          arg::parse_distance_matrix(single_spaced(read_gzip_file(entry.path().string())));
    } catch (const arg::InputError& e) {
      throw std::runtime_error(entry.path().string() + ": " + e.what());
    }
    if (peer.matrix.n != models)
      throw std::runtime_error(entry.path().string() + ": " + std::to_string(peer.matrix.n) +
                               " models, the set has " + std::to_string(models));
    peers.push_back(std::move(peer));
  }
  std::sort(peers.begin(), peers.end(),
            [](const PeerMatrix& a, const PeerMatrix& b) { return a.method < b.method; });
  return peers;
}

std::string peer_heading(const std::string& method) {
  std::string name = method.substr(0, method.find('-'));
  for (char& c : name) c = char(std::toupper(static_cast<unsigned char>(c)));
  return name;
}

}  // namespace argtool
