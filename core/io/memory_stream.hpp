// An std::istream source over bytes in memory, made of pieces, that can say where it stopped.
#pragma once

#include <cstddef>
#include <streambuf>
#include <string_view>
#include <vector>

namespace arg::io {

// One piece of the stream: a view into the caller's input (`source_offset` is where it starts
// there) or a short synthetic text the reader inserts (`source_offset` == npos).
struct StreamPiece {
  std::string_view bytes;
  std::size_t source_offset = npos;
  static constexpr std::size_t npos = static_cast<std::size_t>(-1);
};

// A read-only, seekable stream buffer over pieces of memory, so that a reader can be fed the
// input with some lines dropped or a header rewritten, without copying the bulk of the bytes.
// Unlike std::istringstream it keeps no copy and still knows its position after a failed read.
class MemoryStreamBuf : public std::streambuf {
 public:
  explicit MemoryStreamBuf(std::vector<StreamPiece> pieces);

  // Offset of the next byte to be read, counted in the concatenated stream.
  std::size_t position() const;
  // The same position mapped back to the caller's input; npos inside a synthetic piece.
  std::size_t source_position() const;
  std::size_t size() const { return total_; }

 protected:
  int_type underflow() override;
  std::streamsize showmanyc() override;
  std::streamsize xsgetn(char* out, std::streamsize n) override;
  pos_type seekoff(off_type off, std::ios_base::seekdir dir,
                   std::ios_base::openmode which) override;
  pos_type seekpos(pos_type pos, std::ios_base::openmode which) override;

 private:
  void enter(std::size_t piece, std::size_t offset_in_piece);

  std::vector<StreamPiece> pieces_;
  std::vector<std::size_t> starts_;  // stream offset where each piece begins
  std::size_t current_ = 0;
  std::size_t total_ = 0;
};

// 1-based line number of byte `offset` of `text` (counting '\n').
std::size_t line_of_offset(std::string_view text, std::size_t offset);

}  // namespace arg::io
