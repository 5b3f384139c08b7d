// libFuzzer target: the arg_ivf index's page readers (search/ivf_page.hpp), and what the
// server reads from an accepted item: a cell's centre, an entry's sketch by its coarse
// distance and by the strict reader.
#include <algorithm>
#include <string>

#include "fuzz_support.hpp"
#include "search/coarse_sketch.hpp"
#include "search/ivf_page.hpp"
#include "search/shape_sketch.hpp"

namespace arg::fuzz {

inline int fuzz_ivf_page(const std::uint8_t* data, std::size_t size) {
  constexpr std::size_t kPage = 8192;
  if (size == 0) return 0;
  // The first byte picks the kind the reader expects (the page's own LSN bytes, which no
  // check reads); the rest is the page, cut or padded with zeros to a page's size.
  const ivf::PageKind kind = ivf::PageKind(1 + data[0] % 3);
  std::string page(reinterpret_cast<const char*>(data), std::min(size, kPage));
  page.resize(kPage, '\0');
  const auto* p = reinterpret_cast<const unsigned char*>(page.data());
  ivf::PageFacts facts;
  if (ivf::check_page(p, kPage, kind, &facts)) return 0;
  ARG_FUZZ_CHECK(facts.lower <= facts.upper && facts.upper <= facts.special &&
                 facts.special + ivf::kSpecialSize == kPage);
  if (kind == ivf::PageKind::kMeta) {
    ivf::MetaFields meta;
    if (!ivf::read_meta(p, facts, &meta) && !ivf::check_meta_counts(meta, 100, 4096))
      ARG_FUZZ_CHECK(meta.cells >= 1 && meta.cell_pages <= meta.cells && meta.cell_pages < 100);
    return 0;
  }
  static const CoarseQuery query = [] {
    ShapeSketch s;
    s.has_panorama = s.has_spectrum = true;
    for (float& x : s.spectrum) x = 1;
    return coarse_query(s);
  }();
  // Every item, as the server would read it: none may reach outside the page.
  for (std::uint32_t item = 1; item <= facts.items + 1; ++item) {
    std::string_view bytes;
    const bool cell = kind == ivf::PageKind::kCell;
    const std::size_t head = cell ? ivf::kCellHeadSize : ivf::kEntryHeadSize + 1;
    if (ivf::page_item(p, facts, item, head, head + ivf::kMaxSketchBytes, &bytes)) continue;
    ARG_FUZZ_CHECK(bytes.data() >= page.data() + facts.upper &&
                   bytes.data() + bytes.size() <= page.data() + facts.special);
    std::string_view sketch;
    if (cell) {
      ivf::CellItem c;
      if (ivf::read_cell_item(bytes, &c)) continue;
      if (c.first != ivf::kNoBlock) ivf::check_link(c.first, 2, 1000);
      sketch = c.centre;
    } else {
      ivf::Entry e;
      if (ivf::read_entry(bytes, &e)) continue;
      ARG_FUZZ_CHECK(e.offset >= 1 && !e.sketch.empty());
      sketch = e.sketch;
    }
    const double coarse = coarse_sketch_distance(query, sketch);
    ARG_FUZZ_CHECK(!(coarse < 0));
    try {
      ShapeSketch s;
      read_shape_sketch(sketch, s);
      ARG_FUZZ_CHECK(coarse_sketch_distance(query, sketch) == coarse);
    } catch (const Error&) {
    }
  }
  return 0;
}

}  // namespace arg::fuzz

ARG_FUZZ_ENTRY(arg::fuzz::fuzz_ivf_page)
