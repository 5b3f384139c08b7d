// Running one of OpenMesh's mesh readers over bytes in memory, under a lock and without logging.
#include "io/openmesh_reader.hpp"

#include <istream>
#include <mutex>
#include <new>

#include <OpenMesh/Core/IO/reader/OBJReader.hh>
#include <OpenMesh/Core/IO/reader/OFFReader.hh>
#include <OpenMesh/Core/IO/reader/PLYReader.hh>
#include <OpenMesh/Core/IO/reader/STLReader.hh>
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

bool run_openmesh_reader(OpenMeshReader reader, MemoryStreamBuf& buffer, SoupImporter& importer,
                         OpenMesh::IO::Options& options, bool fail_on_bad_read,
                         const std::function<std::string()>& describe_failure) {
  std::lock_guard<std::mutex> lock(reader_mutex());
  silence_openmesh();
  std::istream in(&buffer);
  in.exceptions(fail_on_bad_read ? std::ios::failbit | std::ios::badbit : std::ios::badbit);
  try {
    switch (reader) {
      case OpenMeshReader::Off:
        return OpenMesh::IO::OFFReader().read(in, importer, options);
      case OpenMeshReader::Obj:
        return OpenMesh::IO::OBJReader().read(in, importer, options);
      case OpenMeshReader::Ply:
        return OpenMesh::IO::PLYReader().read(in, importer, options);
      case OpenMeshReader::Stl:
        return OpenMesh::IO::STLReader().read(in, importer, options);
    }
  } catch (const Error&) {
    throw;
  } catch (const std::bad_alloc&) {
    throw;
  } catch (const std::exception&) {
    // std::ios_base::failure from a failed extraction: the body is shorter or other than declared.
    throw InputError(describe_failure());
  }
  return false;
}

}  // namespace arg::io
