# The core's libraries by layer, each with its sources listed (a new file joins a layer here).
#
#   argmethod  the shape-search method: read, clean, mu, Reeb graph, attributes, ARG, matching
#   arggen     the procedural model generator (sample catalogue, tests, fuzz seeds, arg_generate)
#   argrender  pictures of models, graphs and matches (argtool, arg_inspect's SVG)
#   argeval    retrieval evaluation: labels, metrics, baselines, weight search (argtool, tests)
#
# arg.so links argmethod and, for arg_generate and arg_inspect, arggen and argrender; never
# argeval. Plain C++17, no PostgreSQL headers; position independent (linked into the extension).

set(ARG_METHOD_SOURCES
    common/base64.cpp common/build_options.cpp common/heap_usage.cpp common/key_values.cpp
    common/limits.cpp common/parallel_for.cpp
    mesh/append_faces.cpp mesh/boundary_loops.cpp mesh/bridge_pieces.cpp mesh/clean_mesh.cpp
    mesh/coincident_vertices.cpp mesh/collapse_short_edges.cpp mesh/connected_components.cpp
    mesh/distance_field.cpp mesh/face_subset.cpp mesh/fill_holes.cpp
    mesh/marching_tetrahedra.cpp mesh/mesh_edges.cpp mesh/nearest_points.cpp mesh/normal_pose.cpp
    mesh/normalize_pose.cpp mesh/restrict_face_values.cpp mesh/restrict_vertex_positions.cpp
    mesh/stitch_pieces.cpp
    mesh/surface_area.cpp
    mesh/surface_roughness.cpp mesh/taubin_smoothing.cpp mesh/watertight_proxy.cpp
    # io: one parser per mesh format (see each reader's header comment), images, GLB, writers
    io/decode_image.cpp io/detect_format.cpp io/glb_container.cpp io/gltf_accessor.cpp
    io/image_decoder.cpp io/image_format_checks.cpp io/memory_stream.cpp io/off_header.cpp
    io/openmesh_reader.cpp io/ply_body.cpp io/ply_header.cpp io/polygon_soup.cpp
    io/read_glb.cpp io/read_mesh.cpp io/read_obj.cpp io/read_off.cpp io/read_off_binary.cpp
    io/read_ply.cpp io/read_stl.cpp io/read_stl_ascii.cpp io/soup_importer.cpp
    io/soup_to_mesh.cpp io/text_scan.cpp io/texture_sampling.cpp io/tinygltf_impl.cpp
    io/triangulate_polygon.cpp io/write_mesh.cpp
    mu/dijkstra.cpp mu/geodesic_integral.cpp mu/lane_steps.cpp mu/mu_function.cpp mu/surface_graph.cpp
    reeb/reeb_levels.cpp reeb/slice_intervals.cpp
    graph/arg_graph.cpp graph/comparable.cpp graph/compact_nodes.cpp graph/node_bound.cpp
    graph/panorama_codes.cpp graph/quantise.cpp graph/serialize.cpp
    features/curvature.cpp features/depth_buffer_descriptor.cpp features/depth_images.cpp
    features/laplace_spectrum.cpp features/node_attributes.cpp features/panorama_descriptor.cpp
    features/panoramic_views.cpp features/shape_distributions.cpp
    features/vessel_profile.cpp features/surface_detail.cpp
    match/child_halves.cpp match/match_prep.cpp match/mpair.cpp match/node_similarity.cpp
    match/packed_graph.cpp match/part_match.cpp match/sim_key.cpp match/similarity.cpp
    match/similarity_terms.cpp match/subgraph.cpp match/term_weights.cpp match/weights.cpp
    search/coarse_sketch.cpp search/query_ranker.cpp search/search_descriptor.cpp
    search/shape_sketch.cpp
    search/ivf_page.cpp search/sketch_cells.cpp
    pipeline/build_arg.cpp pipeline/build_memory.cpp pipeline/node_positions.cpp
    pipeline/node_region.cpp
    pipeline/pool_fragments.cpp pipeline/prepare_surface.cpp pipeline/surface_texture.cpp)
set(ARG_GEN_SOURCES
    gen/creature_models.cpp gen/furniture_models.cpp gen/generate_models.cpp
    gen/implicit_solid.cpp gen/marching_tetrahedra.cpp gen/model_blueprints.cpp
    gen/perturb_mesh.cpp gen/portable_math.cpp gen/seeded_random.cpp gen/torus_model.cpp
    gen/vessel_models.cpp)
set(ARG_RENDER_SOURCES
    render/bitmap_font.cpp render/canvas.cpp render/colour_legend.cpp render/colour_map.cpp
    render/contact_sheet.cpp render/draw_shapes.cpp render/graph_overlay.cpp
    render/graph_svg.cpp render/match_picture.cpp render/rasterise_mesh.cpp
    render/render_model.cpp render/upright_frame.cpp render/view_camera.cpp)
set(ARG_EVAL_SOURCES
    eval/baseline_descriptors.cpp eval/csv_records.cpp eval/distance_matrix_file.cpp
    eval/label_file.cpp eval/perturbations.cpp eval/pr_plot.cpp eval/quadric_decimation.cpp
    eval/refine_faces.cpp
    eval/retrieval_metrics.cpp eval/set_weights_file.cpp eval/term_matrices.cpp
    eval/value_jitter.cpp eval/weight_search.cpp)
# The plug-ins' sources, listed with their targets in CMakeLists.txt.
set(ARG_PLUGIN_SOURCES oiio/oiio_decode_image.cpp oiio/write_png.cpp oiio/register_decoder.cpp
                       vdb/vdb_distance_field.cpp vdb/register_distance_field.cpp)

# A source file in core/ that no list names would silently be left out of every library.
file(GLOB_RECURSE arg_found RELATIVE ${CMAKE_SOURCE_DIR}/core CONFIGURE_DEPENDS
     ${CMAKE_SOURCE_DIR}/core/*.cpp)
set(arg_listed ${ARG_METHOD_SOURCES} ${ARG_GEN_SOURCES} ${ARG_RENDER_SOURCES}
               ${ARG_EVAL_SOURCES} ${ARG_PLUGIN_SOURCES})
list(REMOVE_ITEM arg_found ${arg_listed})
if(arg_found)
  message(FATAL_ERROR "core/libraries.cmake lists no library for: ${arg_found}")
endif()

function(arg_core_library name)
  list(TRANSFORM ARGN PREPEND ${CMAKE_SOURCE_DIR}/core/)
  add_library(${name} STATIC ${ARGN})
  target_include_directories(${name} PUBLIC ${CMAKE_SOURCE_DIR}/core)
  target_compile_definitions(${name} PUBLIC ARG_VERSION="${PROJECT_VERSION}" _USE_MATH_DEFINES)
endfunction()

arg_core_library(argmethod ${ARG_METHOD_SOURCES})
# OpenMesh: the OBJ reader (core/io/read_obj.cpp).
target_link_libraries(argmethod PUBLIC Eigen3::Eigen OpenMeshCore nlohmann_json::nlohmann_json
                                       ZLIB::ZLIB Threads::Threads)
arg_core_library(arggen ${ARG_GEN_SOURCES})
target_link_libraries(arggen PUBLIC argmethod)
arg_core_library(argrender ${ARG_RENDER_SOURCES})
target_link_libraries(argrender PUBLIC argmethod)
arg_core_library(argeval ${ARG_EVAL_SOURCES})
# OpenMesh's tools: the quadric decimater of the robustness benchmark (eval/quadric_decimation.cpp).
target_link_libraries(argeval PUBLIC arggen argmethod OpenMeshTools)
