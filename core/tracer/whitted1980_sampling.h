// Whitted's adaptive antialiasing ("An Improved Illumination Model for Shaded
// Display", 1980, section 4): rays through the corners of the pixels rather
// than their centres, each corner shared by the four pixels that meet there;
// a pixel whose corners differ by more than a threshold is cut into four, the
// new corners traced (again shared between the quarters, and with the
// neighbouring pixels), and so on down to a depth limit. A cell's colour is
// the mean of its corners; a pixel's, the mean of its quarters'.
//
// Every corner is a pure function of its place in the picture, and whether a
// cell is cut a function of its corners, so the picture is the same whatever
// the threads and tiles (RenderOptions::whitted1980).
#pragma once

#include <cstdint>
#include <vector>

namespace whitted {

struct Whitted1980Sampling {
    // A cell is cut when two of its corners differ by more than this in any
    // channel, in the 8-bit sRGB codes the picture is shown in.
    double threshold = 8.0;
    // How many times a pixel may be cut: at most 4^maxLevels cells, whose
    // corners are (2^maxLevels + 1)^2 rays; [0, kMaxWhitted1980Levels].
    int maxLevels = 2;
};

inline constexpr int kMaxWhitted1980Levels = 6;

// How deep each pixel of a render was cut (0: its four corners alone), row
// by row; what the editor's subdivision map shows.
struct SubdivisionLevels {
    int width = 0, height = 0;
    std::vector<std::uint8_t> levels;
    int at(int x, int y) const { return levels[std::size_t(y) * width + x]; }
};

}  // namespace whitted
