// The Render tab's choice of antialiasing: the scene's samples per pixel (or a
// quality target's, Render to) or Whitted's own 1980 sampling, rays at the
// pixels' corners and a pixel cut in four where they differ, with its
// threshold and the most cuts a pixel may take. An editor setting, as the
// target is (document/quality_choice.h): not saved in the scene, no undo step.
#pragma once

class QFormLayout;

namespace whitted::ui {

class QualityChoice;

// Adds the rows to `form`, under its "renderSamples" field: "renderSampler"
// (a combo box), and, shown while Whitted 1980 is chosen, "samplerThreshold"
// and "samplerSubdivisions".
void addSamplerRows(QFormLayout* form, QualityChoice* quality);

}  // namespace whitted::ui
