// How long a render of a scene will take on this machine, from small timed
// renders of it (issue 15, item 3: the Render tab's predicted time).
//
// A ray's cost depends on the scene (how many spheres a ray passes near),
// on the sample (a pixel's centre, traced in coherent rows, costs a half to a
// third of a jittered sample on a few balls), and on the picture's size: the finer the
// pixels, the more alike the rays of a row, the fewer nodes of the tree they
// visit. The probe times pixel centres and jittered samples at two sizes, a
// side and half of it, and carries the cost a ray down to the picture's size
// along the power of size they show (0.05 per doubling on three balls, 0.3
// to 0.6 on fields of hundreds; docs/quality.md), each doubling past the
// side gaining half what the one before did: the rays of a row cannot grow
// more alike than alike.
//
// The probes count CPU time, not wall time: the editor probes while its view
// renders on the same cores, where a probe's wall time would count the time
// it waits for them. The render's seconds are that
// CPU time shared among the threads it will run on.
#pragma once

#include "scene/scene.h"
#include "tracer/renderer.h"

namespace whitted {

struct RayCost {
    // CPU seconds a ray: of a one-sample render (pixel centres only) and of a
    // render of more samples a pixel (jittered only).
    double centre = 0.0, jittered = 0.0;
};

struct SpeedProbe {
    double overheadSeconds = 0.0;  // before the first tile: the tree built, the image set up
    int side = 0;                  // the larger probe's longest side, pixels
    RayCost atSide, atHalfSide;
    double sizePower = 0.0;  // cost a ray ~ side^-sizePower, from the two probes
};

// Times the scene, at its depth and precision, at `side` and side / 2 pixels
// along its longest side (or its own size, when smaller). Its renders ask
// `stop`; once it says so, the figures mean nothing.
SpeedProbe probeSpeed(const Scene& scene, int side, const StopPredicate& stop = {});

// The seconds of a render of the scene with its own settings that traces `rays`.
double predictSeconds(const SpeedProbe& probe, const Scene& scene, double rays);

}  // namespace whitted
