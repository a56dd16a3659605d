// The scene file's fields, each described once: its key in the file, the
// words a user reads for it (the editor's panel rows, undo entries and
// messages) and the rule its value keeps (SPEC §6). The writer and both
// readers take the keys from here, the validator the rules, and the editor
// the words, so that a field renamed or given another rule changes in one
// place.
#pragma once

#include <string_view>

namespace whitted {

// What a field's value must be. Names, a sphere's material and the precision
// have rules of their own (validateScene, the readers).
enum class FieldRule {
    None,
    Finite,        // every component a finite number
    Colour,        // finite, no component below 0
    Positive,      // > 0
    NonNegative,   // >= 0
    UnitInterval,  // in [0, 1]
    ImageSize,     // in [1, kMaxImageSize]
    Depth,         // in [0, kMaxDepth]
    Samples,       // in [1, kMaxSamplesPerPixel]
    FieldOfView,   // in (0, 180) degrees
};

struct SceneField {
    std::string_view key;    // as the file spells it, within its object
    std::string_view label;  // as the editor's messages and undo entries say it
    FieldRule rule = FieldRule::None;
    // Its row in a property panel, whose page already says the rest
    // ("Position" on the camera's); empty where that is the label.
    std::string_view row = {};
};

namespace scene_field {

// The document.
inline constexpr SceneField kFormat{"format", "Format"};
inline constexpr SceneField kVersion{"version", "Version"};
inline constexpr SceneField kCamera{"camera", "Camera"};
inline constexpr SceneField kRender{"render", "Render settings"};
inline constexpr SceneField kBackground{"background", "Background colour", FieldRule::Colour,
                                        "Background"};
inline constexpr SceneField kAmbient{"ambient", "Ambient colour", FieldRule::Colour, "Ambient"};
inline constexpr SceneField kMaterials{"materials", "Materials"};
inline constexpr SceneField kLights{"lights", "Lights"};
inline constexpr SceneField kSpheres{"spheres", "Spheres"};

// In "camera".
inline constexpr SceneField kCameraPosition{"position", "Camera position", FieldRule::Finite,
                                            "Position"};
inline constexpr SceneField kLookAt{"look_at", "Camera look-at point", FieldRule::Finite,
                                    "Look at"};
inline constexpr SceneField kUp{"up", "Camera up vector", FieldRule::Finite, "Up"};
inline constexpr SceneField kFieldOfView{"vfov_degrees", "Vertical field of view",
                                         FieldRule::FieldOfView, "Vertical FOV"};

// In "render".
inline constexpr SceneField kWidth{"width", "Image width", FieldRule::ImageSize, "Width"};
inline constexpr SceneField kHeight{"height", "Image height", FieldRule::ImageSize, "Height"};
inline constexpr SceneField kDepth{"max_depth", "Max depth", FieldRule::Depth};
inline constexpr SceneField kSamples{"samples_per_pixel", "Samples per pixel", FieldRule::Samples};
inline constexpr SceneField kPrecision{"precision", "Precision"};

// In every material, light and sphere.
inline constexpr SceneField kName{"name", "Name"};

// In a material, and in its "checker".
inline constexpr SceneField kDiffuse{"diffuse", "Diffuse colour", FieldRule::Colour, "Diffuse"};
inline constexpr SceneField kSpecular{"specular", "Specular", FieldRule::NonNegative};
inline constexpr SceneField kShininess{"shininess", "Shininess", FieldRule::NonNegative};
inline constexpr SceneField kReflectivity{"reflectivity", "Reflectivity", FieldRule::UnitInterval};
inline constexpr SceneField kTransparency{"transparency", "Transparency", FieldRule::UnitInterval};
inline constexpr SceneField kIor{"ior", "Index of refraction", FieldRule::Positive};
inline constexpr SceneField kChecker{"checker", "Checker"};
inline constexpr SceneField kCheckerColour{"color", "Checker colour", FieldRule::Colour};
inline constexpr SceneField kCheckerSize{"size", "Checker size", FieldRule::Positive};

// In a light.
inline constexpr SceneField kLightPosition{"position", "Position", FieldRule::Finite};
inline constexpr SceneField kLightColour{"color", "Colour", FieldRule::Colour};
inline constexpr SceneField kIntensity{"intensity", "Intensity", FieldRule::NonNegative};

// In a sphere.
inline constexpr SceneField kCentre{"center", "Centre", FieldRule::Finite};
inline constexpr SceneField kRadius{"radius", "Radius", FieldRule::Positive};
inline constexpr SceneField kSphereMaterial{"material", "Material"};

}  // namespace scene_field

}  // namespace whitted
