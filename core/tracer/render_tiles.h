// The tiles a render cuts the picture into, and the order they are rendered in.
#pragma once

#include <vector>

namespace whitted {

struct Tile {
    int x, y, w, h;
};

// Tiles of `size` pixels, centre-out: the middle of the picture, where people
// look, arrives first.
std::vector<Tile> spiralTiles(int width, int height, int size);

}  // namespace whitted
