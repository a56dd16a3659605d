// How long a render of a scene will take on this machine, from timed renders
// of a few of its own tiles (the Render tab's predicted time).
//
// A ray's cost depends on the scene (how many spheres a ray passes near),
// on the sample (a pixel's centre, traced in coherent rows, costs a half to a
// third of a jittered sample on a few balls), and on the picture's size: the
// finer the pixels, the more alike the rays of a row, the fewer nodes of the
// tree they visit. A shrunken picture cannot show that last part: carried
// from 160 pixels to 640 along the power of size between 80 and 160, the
// cost missed renders by 0.6 to 1.6 times (docs/design/quality-planning.md). So the probe
// renders tiles of the picture itself, at its own size, spread over it (each
// pixel's samples are the picture's, bit for bit: RenderOptions::regions), at
// most kSpeedProbePixels of them, and times pixel centres and jittered samples.
//
// The probes count CPU time, not wall time: the editor probes while its view
// renders on the same cores, where a probe's wall time would count the time
// it waits for them. The render's seconds are that
// CPU time shared among the threads it will run on.
#pragma once

#include <vector>

#include "image/image.h"
#include "scene/scene.h"
#include "tracer/renderer.h"

namespace whitted {

// The pixels the probe times: as many as a 160x120 picture's.
inline constexpr int kSpeedProbePixels = 160 * 120;
inline constexpr int kSpeedProbeTileSide = 16;

struct RayCost {
    // CPU seconds a ray: of a one-sample render (pixel centres only) and of a
    // render of more samples a pixel (jittered only).
    double centre = 0.0, jittered = 0.0;
};

struct SpeedProbe {
    double overheadSeconds = 0.0;  // before the first tile: the tree built, the image set up
    RayCost cost;                  // a ray of the picture's tiles
    int pixels = 0;                // timed to find it
};

// The pixels the probe renders: the whole of a picture of at most `pixels`,
// else about `pixels`' worth in tiles of kSpeedProbeTileSide spread over
// the picture, one in each band of columns, its height following the
// golden ratio, so that sky, balls and floor all take part. Small tiles in
// many places: the balls of a field are not spread evenly, and 19 tiles of
// the render's 32 pixels missed a field's time by a third.
std::vector<PixelRect> probeTiles(int width, int height, int pixels);

// Times the scene, at its size, depth and precision, on probeTiles(). Its
// renders ask `stop`; once it says so, the figures mean nothing.
SpeedProbe probeSpeed(const Scene& scene, int pixels = kSpeedProbePixels,
                      const StopPredicate& stop = {});

// A render of one pixel of the scene, in the CPU time of the calling thread,
// which prepares the scene: what any render pays before its first tile.
double renderOverheadSeconds(const Scene& scene, const StopPredicate& stop = {});

// The seconds of a render of the scene with its own settings that traces `rays`.
double predictSeconds(const SpeedProbe& probe, const Scene& scene, double rays);

}  // namespace whitted
