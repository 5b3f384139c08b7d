// Seeded transformations of a mesh for the robustness benchmark (after SHREC 2010's protocol).
#pragma once

#include <cstdint>
#include <optional>
#include <string_view>
#include <vector>

#include "mesh/mesh.hpp"

namespace arg {

// What a scan or an export does to a model, each at strengths 1 (mild) to 5 (harsh). D is the
// diagonal of the model's bounding box; areas are shares of the model's surface. A point is a
// position on the surface: the corners of a soup's triangles that meet there without sharing an
// index move together and count once, so noise displaces a soup without tearing it apart.
enum class Perturbation {
  SmallHoles,  // 4 s holes of radius 0.02 D: the faces whose centre lies within it of a point
               // drawn uniformly on the surface, faces the hole's rim crosses cut finer first
  LargeHoles,  // s holes of radius 0.06 D
  Noise,       // Gaussian offset of every point, sigma 0.001 s D per axis
  ShotNoise,   // 0.2 s % of the points pushed 0.02 D along their normal, either way
  Decimate,    // quadric error edge collapses down to 50 - 7.5 (s - 1) % of the points (50% ..
               // 20%), or as far as collapses go on a soup whose triangles share too few edges
  Remesh,      // midpoint subdivision, then edge collapse to (0.75 + 0.25 s) x the points:
               // the same surface with another triangulation
  Split,       // s random planes through the middle cut the surface into separate parts
  Partial,     // the part of the surface nearest a random point, 5 s % of the area, removed
  Scale,       // the whole model scaled by 2^s
  LocalScale,  // a ball of radius 0.2 D about a surface point grown by up to 15 s %
  Cluster,     // vertex clustering (Rossignac and Borrel) on a shifted grid down to the vertex
               // count of Decimate: what a crude exporter does, non-manifold bits and slivers
};

const std::vector<Perturbation>& all_perturbations();
const char* perturbation_name(Perturbation kind);  // "small_holes", "noise", ...
std::optional<Perturbation> parse_perturbation(std::string_view name);

// Applies `kind` at `strength` (1..5). The same mesh, kind, strength and seed give the same
// mesh, bit for bit. Colours follow their faces. Throws InputError for a strength outside 1..5
// or a mesh without faces, and when nothing would be left.
Mesh perturb(const Mesh& mesh, Perturbation kind, int strength, std::uint64_t seed);

}  // namespace arg
