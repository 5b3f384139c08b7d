# The core's folders in stage order, and a configure-time check that no folder includes one
# above it: a mesh goes up through the method's stages (common .. pipeline); the generator, the
# evaluation, the pictures and the plug-ins sit above the method and use it. docs/DESIGN.md
# draws the same order. A new folder must be placed here before it configures.
set(ARG_STAGES
    common    # errors, limits, byte and text codecs, build options, strict maths
    mesh      # the triangle mesh and what is done to it (clean, pose, proxy, holes)
    io        # mesh and image readers and writers
    mu        # mu, the integral of geodesic distance
    reeb      # mu intervals, their regions, the Reeb levels
    graph     # the stored ARG: record, node bound, binary format and codecs
    features  # what a node and a whole shape carry (attributes, panorama, spectrum)
    match     # MPAIR, SIM and how it mixes its terms
    search    # sketches, search descriptors, cells: what an index keeps and compares
    pipeline  # the build from bytes to a stored ARG
    gen       # the model generator
    eval      # retrieval evaluation and weight search
    render    # pictures
    oiio      # the OpenImageIO plug-in
    vdb)      # the OpenVDB plug-in

cmake_policy(SET CMP0057 NEW)  # IN_LIST, also when run as a script
# Also runs as a script on another tree (tests/layering): cmake -DARG_CORE_DIR=DIR -P stages.cmake
if(NOT ARG_CORE_DIR)
  set(ARG_CORE_DIR ${CMAKE_SOURCE_DIR}/core)
endif()
if(CMAKE_SCRIPT_MODE_FILE)
  set(arg_reglob)
else()
  set(arg_reglob CONFIGURE_DEPENDS)
endif()

file(GLOB arg_folders LIST_DIRECTORIES true RELATIVE ${ARG_CORE_DIR} ${ARG_CORE_DIR}/*)
foreach(folder IN LISTS arg_folders)
  if(IS_DIRECTORY ${ARG_CORE_DIR}/${folder} AND NOT folder IN_LIST ARG_STAGES)
    message(FATAL_ERROR "core/stages.cmake: place core/${folder} in ARG_STAGES")
  endif()
endforeach()

set(arg_upward)
foreach(stage IN LISTS ARG_STAGES)
  list(FIND ARG_STAGES ${stage} own)
  file(GLOB arg_stage_files ${arg_reglob} ${ARG_CORE_DIR}/${stage}/*.cpp
       ${ARG_CORE_DIR}/${stage}/*.hpp)
  foreach(file IN LISTS arg_stage_files)
    file(STRINGS ${file} includes REGEX "^#include \"[a-z_]+/")
    foreach(line IN LISTS includes)
      string(REGEX REPLACE "^#include \"([a-z_]+)/.*" "\\1" target "${line}")
      list(FIND ARG_STAGES ${target} other)
      if(other GREATER own)
        file(RELATIVE_PATH shown ${ARG_CORE_DIR} ${file})
        list(APPEND arg_upward "core/${shown} includes ${target}/ (a later stage)")
      endif()
    endforeach()
  endforeach()
endforeach()
if(arg_upward)
  list(JOIN arg_upward "\n  " arg_upward_text)
  message(FATAL_ERROR "core/stages.cmake: includes against the stage order:\n  ${arg_upward_text}")
endif()
