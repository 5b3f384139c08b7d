// Colour maps: mu to colour for surfaces and legends, and distinct colours for matched pairs.
#pragma once

#include "render/canvas.hpp"

namespace arg {

// A rainbow-like map with even lightness steps (Google's Turbo, polynomial fit) with its darkest
// ends cut off, so that shaded surfaces stay readable: t = 0 blue, 0.5 green-yellow, 1 red.
// t is clamped to [0, 1].
Rgb mu_colour(double t);

// The k-th of a fixed list of colours that stay apart from each other and from grey; after the
// list is used up it repeats, darker and lighter by turns.
Rgb pair_colour(int k);

}  // namespace arg
