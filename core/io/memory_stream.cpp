// An std::istream source over bytes in memory, made of pieces, that can say where it stopped.
#include "io/memory_stream.hpp"

#include <algorithm>
#include <cstring>

namespace arg::io {

MemoryStreamBuf::MemoryStreamBuf(std::vector<StreamPiece> pieces) {
  for (const StreamPiece& piece : pieces) {
    if (piece.bytes.empty()) continue;
    starts_.push_back(total_);
    total_ += piece.bytes.size();
    pieces_.push_back(piece);
  }
  if (pieces_.empty()) {
    setg(nullptr, nullptr, nullptr);
  } else {
    enter(0, 0);
  }
}

void MemoryStreamBuf::enter(std::size_t piece, std::size_t offset_in_piece) {
  current_ = piece;
  // std::streambuf wants non-const pointers; the get area is never written through.
  char* begin = const_cast<char*>(pieces_[piece].bytes.data());
  setg(begin, begin + offset_in_piece, begin + pieces_[piece].bytes.size());
}

std::size_t MemoryStreamBuf::position() const {
  if (pieces_.empty()) return 0;
  return starts_[current_] + static_cast<std::size_t>(gptr() - eback());
}

std::size_t MemoryStreamBuf::source_position() const {
  if (pieces_.empty()) return 0;
  const StreamPiece& piece = pieces_[current_];
  if (piece.source_offset == StreamPiece::npos) return StreamPiece::npos;
  return piece.source_offset + static_cast<std::size_t>(gptr() - eback());
}

MemoryStreamBuf::int_type MemoryStreamBuf::underflow() {
  if (pieces_.empty()) return traits_type::eof();
  while (gptr() == egptr()) {
    if (current_ + 1 >= pieces_.size()) return traits_type::eof();
    enter(current_ + 1, 0);
  }
  return traits_type::to_int_type(*gptr());
}

std::streamsize MemoryStreamBuf::showmanyc() {
  const std::size_t left = total_ - position();
  return left == 0 ? -1 : static_cast<std::streamsize>(left);
}

std::streamsize MemoryStreamBuf::xsgetn(char* out, std::streamsize n) {
  std::streamsize done = 0;
  while (done < n) {
    if (gptr() == egptr() && traits_type::eq_int_type(underflow(), traits_type::eof())) break;
    const std::streamsize chunk = std::min<std::streamsize>(n - done, egptr() - gptr());
    std::memcpy(out + done, gptr(), static_cast<std::size_t>(chunk));
    setg(eback(), gptr() + chunk, egptr());  // gbump takes an int: pieces may be larger
    done += chunk;
  }
  return done;
}

MemoryStreamBuf::pos_type MemoryStreamBuf::seekoff(off_type off, std::ios_base::seekdir dir,
                                                   std::ios_base::openmode which) {
  off_type base = 0;
  if (dir == std::ios_base::cur) {
    base = static_cast<off_type>(position());
  } else if (dir == std::ios_base::end) {
    base = static_cast<off_type>(total_);
  }
  return seekpos(pos_type(base + off), which);
}

MemoryStreamBuf::pos_type MemoryStreamBuf::seekpos(pos_type pos, std::ios_base::openmode which) {
  const off_type target = static_cast<off_type>(pos);
  if (!(which & std::ios_base::in) || target < 0 || static_cast<std::size_t>(target) > total_) {
    return pos_type(off_type(-1));
  }
  if (pieces_.empty()) return pos;
  const std::size_t t = static_cast<std::size_t>(target);
  if (t == total_) {
    enter(pieces_.size() - 1, pieces_.back().bytes.size());
    return pos;
  }
  const auto it = std::upper_bound(starts_.begin(), starts_.end(), t);
  const std::size_t piece = static_cast<std::size_t>(it - starts_.begin()) - 1;
  enter(piece, t - starts_[piece]);
  return pos;
}

std::size_t line_of_offset(std::string_view text, std::size_t offset) {
  offset = std::min(offset, text.size());
  return 1 + static_cast<std::size_t>(std::count(text.begin(), text.begin() + offset, '\n'));
}

}  // namespace arg::io
