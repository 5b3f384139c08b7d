// argtool ingest: a folder of meshes (and its catalogue) to COPY rows with their ARGs, built on
// every core.
//
// One row per mesh file under the folder, in path order whatever the thread count: the
// catalogue's fields (the file column holding the path relative to the folder; no catalogue:
// that path alone), then the ARG in its text form, which is what arg_out prints and arg_in reads,
// and equals arg_build(mesh, options) of the same file. A file that does not build is reported
// on stderr, on a line of its own in the same order, and left out; the others load.
#include <chrono>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <memory>
#include <mutex>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include "command_registry.hpp"
#include "common/parallel_for.hpp"
#include "copy_text.hpp"
#include "graph/serialize.hpp"
#include "ingest_list.hpp"
#include "load_arg.hpp"
#include "pipeline/build_arg.hpp"
#include "progress_bar.hpp"

namespace {

struct IngestArgs {
  std::string dir, catalogue, table, arg_column = "descr", out = "-";
  int threads = int(std::max(1u, std::thread::hardware_concurrency()));
  bool strict = false;
  arg::BuildOptions options;
};

// The row of one item, with its newline; throws what the build throws.
std::string make_row(const argtool::IngestItem& item, const arg::BuildOptions& options) {
  const std::string bytes =
      arg::build_arg_bytes(argtool::read_file_bytes(item.path), {}, options, arg::Limits{});
  std::string row;
  for (const std::string& field : item.fields) {
    if (field.empty())
      row += argtool::kCopyNull;
    else
      argtool::append_copy_field(row, field);
    row += '\t';
  }
  return row + arg::arg_to_text(bytes) + '\n';
}

// "COPY table ("a", "b", "descr") FROM STDIN;": the line that makes the rows a psql script.
std::string copy_statement(const IngestArgs& a, const std::vector<std::string>& columns) {
  std::string list;
  for (const std::string& c : columns) list += argtool::copy_column_name(c) + ", ";
  return "COPY " + a.table + " (" + list + argtool::copy_column_name(a.arg_column) +
         ") FROM STDIN;\n";
}

int run_ingest(IngestArgs& a) {
  const auto t0 = std::chrono::steady_clock::now();
  const argtool::IngestList list = argtool::list_ingest(a.dir, a.catalogue);
  for (const std::string& problem : list.problems) std::fprintf(stderr, "%s\n", problem.c_str());
  const std::size_t n = list.items.size();
  if (n == 0) throw std::runtime_error("no .off .obj .ply .stl or .glb files under " + a.dir);
  std::string columns;
  for (const std::string& c : list.columns) columns += c + ", ";
  std::fprintf(stderr, "ingest: %zu mesh files; columns %s%s\n", n, columns.c_str(),
               a.arg_column.c_str());

  std::ofstream file;
  std::ostream* out = &std::cout;
  if (a.out != "-") {
    file.open(a.out, std::ios::binary | std::ios::trunc);
    if (!file) throw std::runtime_error("cannot write " + a.out);
    out = &file;
  }
  if (!a.table.empty()) *out << copy_statement(a, list.columns);

  // Each build runs on one thread: the models are the parallel work. Rows wait in their slots
  // until every earlier one is written, so the output is in path order; whoever fills the next
  // slot writes it (and any ready after it) under the lock, errors included.
  a.options.threads = 1;
  std::vector<std::string> rows(n), errors(n);
  std::vector<char> ready(n, 0);
  std::size_t next = 0, failed = 0, bytes_out = 0;
  std::mutex lock;
  argtool::ProgressLine progress("ingest", n, "models");
  arg::parallel_for(n, a.threads, [&](std::size_t i) {
    std::string row, error;
    try {
      row = make_row(list.items[i], a.options);
    } catch (const std::exception& e) {
      error = e.what();
      if (error.empty()) error = "failed";
    }
    {
      const std::lock_guard<std::mutex> guard(lock);
      rows[i] = std::move(row);
      errors[i] = std::move(error);
      ready[i] = 1;
      for (; next < n && ready[next]; ++next) {
        if (errors[next].empty()) {
          out->write(rows[next].data(), std::streamsize(rows[next].size()));
          bytes_out += rows[next].size();
        } else {
          progress.note("ingest: skipped " + list.items[next].file + ": " + errors[next]);
          ++failed;
        }
        std::string().swap(rows[next]);
        std::string().swap(errors[next]);
      }
    }
    progress.advance();
  });
  progress.finish();
  if (!a.table.empty()) *out << "\\.\n";
  out->flush();
  if (!*out)
    throw std::runtime_error("cannot write the rows to " + (a.out == "-" ? "stdout" : a.out));

  const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  std::fprintf(stderr,
               "ingest: %zu of %zu models in %.1f s (%.1f models/s, %d threads), %zu skipped, "
               "%.1f MB of rows\n",
               n - failed, n, s, double(n) / s, a.threads, failed, double(bytes_out) / 1e6);
  if (failed == n) return 1;
  return a.strict && (failed > 0 || !list.problems.empty()) ? 1 : 0;
}

const bool registered = argtool::register_command(
    "ingest",
    "build the ARGs of every mesh under a folder on all cores, as COPY rows with the catalogue's "
    "fields",
    [](CLI::App& app) {
      auto a = std::make_shared<IngestArgs>();
      app.add_option("dir", a->dir, "folder of .off .obj .ply .stl .glb files (and subfolders)")
          ->required()
          ->check(CLI::ExistingDirectory);
      app.add_option("--catalogue", a->catalogue,
                     "CSV with a header and a file (or path) column naming each mesh relative "
                     "to DIR: its columns come first in each row")
          ->check(CLI::ExistingFile);
      app.add_option("--threads", a->threads, "models built at once (default: every core)")
          ->check(CLI::Range(1, 256));
      app.add_option("--table", a->table,
                     "write a psql script: COPY TABLE (columns) FROM STDIN, the rows, \\.");
      app.add_option("--arg-column", a->arg_column, "the ARG's column in COPY's column list")
          ->capture_default_str();
      app.add_option("-o,--output", a->out, "file to write the rows to (- for stdout)")
          ->capture_default_str();
      app.add_flag("--strict", a->strict,
                   "exit 1 when a file is skipped or a catalogue row names no mesh (default: "
                   "only when every file is skipped)");
      argtool::add_build_flags(app, a->options, false);
      return [a] { return run_ingest(*a); };
    });

}  // namespace
