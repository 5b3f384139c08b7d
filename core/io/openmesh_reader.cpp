// Running OpenMesh's OBJ reader over bytes in memory, under a lock and without logging.
#include "io/openmesh_reader.hpp"

#include <istream>
#include <mutex>
#include <new>

#include <OpenMesh/Core/IO/reader/OBJReader.hh>
#include <OpenMesh/Core/System/omstream.hh>

#include "common/errors.hpp"

namespace arg::io {

namespace {

std::mutex& reader_mutex() {
  static std::mutex mutex;
  return mutex;
}

void silence_openmesh() {
  static std::once_flag once;
  std::call_once(once, [] {
    omerr().disable();
    omlog().disable();
    omout().disable();
  });
}

}  // namespace

bool run_openmesh_obj_reader(MemoryStreamBuf& buffer, SoupImporter& importer,
                             OpenMesh::IO::Options& options,
                             const std::function<std::string()>& describe_failure) {
  std::lock_guard<std::mutex> lock(reader_mutex());
  silence_openmesh();
  std::istream in(&buffer);
  // Only badbit: the reader tests failbit itself, line by line, to skip what it does not know.
  in.exceptions(std::ios::badbit);
  try {
    return OpenMesh::IO::OBJReader().read(in, importer, options);
  } catch (const Error&) {
    throw;
  } catch (const std::bad_alloc&) {
    throw;
  } catch (const std::exception&) {
    // std::ios_base::failure: the stream broke down.
    throw InputError(describe_failure());
  }
  return false;
}

}  // namespace arg::io
