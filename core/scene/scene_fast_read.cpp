// simdjson's On-Demand API walks the text in order and parses each value where
// the reader asks for it: a million spheres go straight into their structs,
// with no DOM and no token strings between (the full reader's nlohmann lexer
// took half of opening a 1,000,000-sphere file). The spheres array is walked
// twice: once skipping its objects to cut it into parts, then each part read
// on one of several threads. Each helper returns false at the first thing it
// would have to judge; the caller then reads the text again with the full
// reader.
#include "scene/scene_fast_read.h"

#include <algorithm>
#include <atomic>
#include <bit>
#include <cmath>
#include <cstdint>
#include <initializer_list>
#include <new>
#include <string>
#include <string_view>
#include <vector>

#include <simdjson.h>

#include "base/parallel_for.h"
#include "scene/scene_io.h"
#include "scene/scene_json.h"

namespace whitted::detail {
namespace {

namespace od = simdjson::ondemand;
using namespace scene_field;

// Up to 19 digits simdjson rounds a number as correctly as strtod, which the
// full reader's nlohmann uses (and an integer's double is the same exact value
// rounded once), so the two readers give equal doubles. Past 19 digits its
// slower path is wrong in Debian's 3.0.1 (0.599...9375, the exact value of the
// double 0.6, read as 5.9e-35), so such numbers go to the full reader; the
// writer never writes more than 17.
bool number(od::value v, double& out) {
    int digits = 0;  // significant: from the first digit that is not 0
    const std::string_view token = v.raw_json_token();
    if (token.size() > 19)  // else it cannot hold more than 19 digits
        for (const char c : token) {
            if (c == 'e' || c == 'E') break;
            digits += (c >= '1' && c <= '9') || (c == '0' && digits > 0);
        }
    double d = 0;
    if (digits > 19 || v.get_double().get(d) || !std::isfinite(d)) return false;
    out = d;
    return true;
}

// Reader::integer's rule: a whole number no larger than 2e9.
bool integer(od::value v, int& out) {
    double d = 0;
    if (!number(v, d) || d != std::floor(d) || std::fabs(d) > 2e9) return false;
    out = static_cast<int>(d);
    return true;
}

// A control character in a string is left to the full reader: JSON forbids it
// unescaped, which simdjson does not check, and an escaped one reads the same
// either way.
bool text(od::value v, std::string& out) {
    std::string_view s;
    if (v.get_string().get(s)) return false;
    for (const char c : s)
        if (static_cast<unsigned char>(c) < 0x20) return false;
    out.assign(s);
    return true;
}

bool vec3(od::value v, Vec3& out) {
    od::array array;
    if (v.get_array().get(array)) return false;
    int i = 0;
    for (auto element : array) {
        od::value x;
        if (i == 3 || element.get(x) || !number(x, out[i])) return false;
        ++i;
    }
    return i == 3;
}

// Walks an object whose keys must be among `keys`, each at most once, and
// the first `required` of them present; field(i, value) reads key i's value.
template <typename Field>
bool fields(od::value v, std::initializer_list<SceneField> keys, int required, Field&& field) {
    od::object object;
    if (v.get_object().get(object)) return false;
    std::uint32_t seen = 0;
    for (auto entry : object) {
        std::string_view key;
        od::value value;
        if (entry.unescaped_key().get(key) || entry.value().get(value)) return false;
        int i = 0;
        for (const SceneField& k : keys) {
            if (k.key == key) break;
            ++i;
        }
        if (i == int(keys.size()) || (seen >> i & 1u)) return false;
        seen |= 1u << i;
        if (!field(i, value)) return false;
    }
    const std::uint32_t mask = (std::uint32_t(1) << required) - 1;
    return (seen & mask) == mask;
}

bool readCamera(od::value v, Camera& c) {
    return fields(v, {kCameraPosition, kLookAt, kUp, kFieldOfView}, 2, [&](int i, od::value x) {
        switch (i) {
            case 0:
                return vec3(x, c.position);
            case 1:
                return vec3(x, c.lookAt);
            case 2:
                return vec3(x, c.up);
            default:
                return number(x, c.vfovDegrees);
        }
    });
}

bool readPrecision(od::value v, Precision& out) {
    std::string_view name;
    if (v.get_string().get(name)) return false;
    const std::optional<Precision> p = parsePrecision(name);
    if (p) out = *p;
    return p.has_value();
}

bool readRender(od::value v, RenderSettings& r) {
    return fields(v, {kWidth, kHeight, kDepth, kSamples, kPrecision}, 0, [&](int i, od::value x) {
        switch (i) {
            case 0:
                return integer(x, r.width);
            case 1:
                return integer(x, r.height);
            case 2:
                return integer(x, r.maxDepth);
            case 3:
                return integer(x, r.samplesPerPixel);
            default:
                return readPrecision(x, r.precision);
        }
    });
}

bool readChecker(od::value v, std::optional<Checker>& out) {
    Checker c;
    if (!fields(v, {kCheckerColour, kCheckerSize}, 2,
                [&](int i, od::value x) { return i == 0 ? vec3(x, c.color) : number(x, c.size); }))
        return false;
    out = c;
    return true;
}

bool readMaterial(od::value v, Material& m) {
    return fields(
        v, {kName, kDiffuse, kSpecular, kShininess, kReflectivity, kTransparency, kIor, kChecker},
        1, [&](int i, od::value x) {
            switch (i) {
                case 0:
                    return text(x, m.name);
                case 1:
                    return vec3(x, m.diffuse);
                case 2:
                    return number(x, m.specular);
                case 3:
                    return number(x, m.shininess);
                case 4:
                    return number(x, m.reflectivity);
                case 5:
                    return number(x, m.transparency);
                case 6:
                    return number(x, m.ior);
                default:
                    return readChecker(x, m.checker);
            }
        });
}

bool readLight(od::value v, Light& l) {
    return fields(v, {kName, kLightPosition, kLightColour, kIntensity}, 2, [&](int i, od::value x) {
        switch (i) {
            case 0:
                return text(x, l.name);
            case 1:
                return vec3(x, l.position);
            case 2:
                return vec3(x, l.color);
            default:
                return number(x, l.intensity);
        }
    });
}

bool readSphere(od::value v, Sphere& s) {
    return fields(v, {kName, kCentre, kRadius, kSphereMaterial}, 4, [&](int i, od::value x) {
        switch (i) {
            case 0:
                return text(x, s.name);
            case 1:
                return vec3(x, s.center);
            case 2:
                return number(x, s.radius);
            default:
                return text(x, s.material);
        }
    });
}

template <typename T>
bool readList(od::value v, std::vector<T>& out, bool (*readOne)(od::value, T&)) {
    od::array array;
    if (v.get_array().get(array)) return false;
    for (auto element : array) {
        od::value x;
        T item;
        if (element.get(x) || !readOne(x, item)) return false;
        out.push_back(std::move(item));
    }
    return true;
}

// The spheres are read on every core, kSpheresPerPart to a task: parsing
// their numbers was most of opening a million (docs/design/performance.md).
// Small parts keep each reader's memory small: parts of 65,536 took 50 MB
// more at 1M, and longer.
constexpr std::size_t kSpheresPerPart = std::size_t(1) << 12;

// The texts of the array's elements, kSpheresPerPart to a part, each part
// from its first element's '{' to its last's '}', and how many elements
// there are. Skipping an object parses none of its numbers.
bool sphereParts(od::value v, std::vector<std::string_view>& parts, std::size_t& count) {
    od::array array;
    if (v.get_array().get(array)) return false;
    const char* begin = nullptr;
    const char* end = nullptr;
    count = 0;
    for (auto element : array) {
        od::object object;
        std::string_view text;
        if (element.get_object().get(object) || object.raw_json().get(text)) return false;
        if (!begin) begin = text.data();
        end = text.data() + text.size();
        if (++count % kSpheresPerPart == 0) {
            parts.emplace_back(begin, std::size_t(end - begin));
            begin = nullptr;
        }
    }
    if (begin) parts.emplace_back(begin, std::size_t(end - begin));
    return true;
}

// Reads parts of the spheres array, one after another: its parser and its
// copy of a part keep their memory from part to part, since new pages cost
// more than the reading (simdjson's index of a part alone is four bytes a
// byte of text).
struct SpherePartReader {
    od::parser parser;
    std::string array;

    // A part's `count` spheres into out[0, count), read as the array "[" +
    // its text + "]" (simdjson reads a text from its start).
    bool read(std::string_view text, Sphere* out, std::size_t count) {
        array.reserve(text.size() + 2 + simdjson::SIMDJSON_PADDING);
        array.assign("[").append(text).append("]");
        od::document document;
        if (parser.iterate(array.data(), array.size(), array.capacity()).get(document))
            return false;
        od::array elements;
        if (document.get_array().get(elements)) return false;
        std::size_t read = 0;
        for (auto element : elements) {
            od::value x;
            if (read == count || element.get(x) || !readSphere(x, out[read++])) return false;
        }
        return read == count && document.current_location().error() == simdjson::OUT_OF_BOUNDS;
    }
};

bool readSpheres(od::value v, std::vector<Sphere>& out) {
    std::vector<std::string_view> parts;
    std::size_t count = 0;
    if (!sphereParts(v, parts, count)) return false;
    out.resize(count);
    std::atomic<bool> read{true};
    std::atomic<std::size_t> nextPart{0};
    const int workers = int(std::min<std::size_t>(resolveThreadCount(0), parts.size()));
    forChunks(
        workers, workers,
        [&](int) {
            try {
                SpherePartReader reader;
                for (std::size_t p; read && (p = nextPart++) < parts.size();) {
                    const std::size_t first = p * kSpheresPerPart;
                    const std::size_t n = std::min(kSpheresPerPart, count - first);
                    if (!reader.read(parts[p], out.data() + first, n)) read = false;
                }
            } catch (const std::bad_alloc&) {
                read = false;  // the full reader then runs out of memory in its turn
            }
        },
        1);
    return read;
}

bool readFormat(od::value v) {
    std::string_view format;
    return !v.get_string().get(format) && format == kSceneFormatName;
}

bool readVersion(od::value v) {
    int version = 0;
    return integer(v, version) && version >= 1 && version <= kSceneFormatVersion;
}

bool readRoot(od::value root, Scene& scene) {
    return fields(
        root,
        {kFormat, kVersion, kCamera, kRender, kBackground, kAmbient, kMaterials, kLights, kSpheres},
        3, [&](int i, od::value x) {
            switch (i) {
                case 0:
                    return readFormat(x);
                case 1:
                    return readVersion(x);
                case 2:
                    return readCamera(x, scene.camera);
                case 3:
                    return readRender(x, scene.render);
                case 4:
                    return vec3(x, scene.background);
                case 5:
                    return vec3(x, scene.ambient);
                case 6:
                    return readList(x, scene.materials, readMaterial);
                case 7:
                    return readList(x, scene.lights, readLight);
                default:
                    return readSpheres(x, scene.spheres);
            }
        });
}

}  // namespace

std::size_t fastReadPadding() {
    return simdjson::SIMDJSON_PADDING;
}

std::optional<Scene> readSceneFast(const char* text, std::size_t size, std::size_t capacity) {
    od::parser parser;
    od::document document;
    if (parser.iterate(text, size, capacity).get(document)) return std::nullopt;
    od::value root;
    if (document.get_value().get(root)) return std::nullopt;
    Scene scene;
    scene.spheres.reserve(std::size_t(size / kShortestSavedSphere));
    // Past the top-level object, only whitespace: simdjson 3.0 says so by
    // having no current location.
    if (!readRoot(root, scene) || document.current_location().error() != simdjson::OUT_OF_BOUNDS)
        return std::nullopt;
    return scene;
}

}  // namespace whitted::detail
