#include "numerics_report.h"

#include "base/printed.h"

#include <algorithm>
#include <cstdio>

namespace whitted::numerics {

namespace {

std::string percent(double fraction) {
    return fraction == 0.0 ? "0" : printed("%.3f%%", 100.0 * fraction);
}

// In 8-bit display steps: "12.5/255".
std::string steps(float difference) {
    const double s = double(difference) * 255.0;
    if (s == 0.0) return "0";
    return s < 0.05 ? "<0.1/255" : printed("%.1f/255", s);
}

std::string signedK(int k) {
    return k > 0 ? printed("+%d", k) : printed("%d", k);
}

std::string kRange(const RangeSummary& r) {
    if (!r.low) return "nowhere (k = 0 fails)";
    if (*r.low == *r.high) return printed("k = %d only", *r.low);
    return printed("k in [%d, %d]", *r.low, *r.high);
}

std::string failures(const RangeSummary& r) {
    if (!r.low) return "k = 0";
    auto side = [](const std::optional<int>& k) { return k ? signedK(*k) : std::string("none"); };
    if (r.kind == SweepKind::Translate) return side(r.failAbove);
    return side(r.failBelow) + " / " + side(r.failAbove);
}

// The k range each sweep is asked to cover: 10^k within [-4, 4] (float) and [-8, 8] (double);
// 2^k within [-20, 20]; offsets of 1e2 to 1e5 (float) and up to 1e9 (double).
struct Ask {
    int low, high;
};
Ask issueAsks(SweepKind kind, Precision p) {
    const bool f = p == Precision::Float;
    switch (kind) {
        case SweepKind::Scale10:
            return f ? Ask{-4, 4} : Ask{-8, 8};
        case SweepKind::Scale2:
            return {-20, 20};
        case SweepKind::Translate:
            return f ? Ask{0, 5} : Ask{0, 9};
    }
    return {0, 0};
}

std::string askText(SweepKind kind, Ask a) {
    if (kind == SweepKind::Translate) return printed("k up to %d", a.high);
    return printed("k in [%d, %d]", a.low, a.high);
}

std::string metText(const RangeSummary& r, Ask a) {
    if (r.testedLow > a.low || r.testedHigh < a.high) return "not tested";
    return r.low && *r.low <= a.low && *r.high >= a.high ? "**yes**" : "**no**";
}

std::string figures(const PointResult& r) {
    if (r.refused) return "the scene is refused: " + *r.refused;
    std::string s = percent(r.fractionOverOne()) + " of pixels over 1/255, " +
                    percent(r.fractionOverTwo()) + " over 2/255, largest " + steps(r.largest);
    if (r.nonFinite) s += printed(", %zu NaN/Inf pixels", r.nonFinite);
    if (r.bitIdentical) s += *r.bitIdentical ? ", bit-identical" : ", not bit-identical";
    return s;
}

// "1 sample", "2 samples": the report is read as prose.
std::string counted(int n, const char* noun) {
    return std::to_string(n) + " " + noun + (n == 1 ? "" : "s");
}

void header(std::string& md, const ReportContext& c) {
    const RenderSettings& s = c.settings;
    md += "# Numerical range of the tracer: float and double\n\n";
    md += "<!-- Generated file: do not edit. -->\n";
    md += "> **Generated** by `whitted-numerics` (app/numerics/); do not edit by hand.\n";
    md += "> Regenerate with " + c.regenerate + ".\n";
    md += printed("> Settings: `%s` at %d×%d, max depth %d, %s per pixel, %s", c.sceneName.c_str(),
                  s.width, s.height, s.maxDepth, counted(s.samplesPerPixel, "sample").c_str(),
                  counted(c.threads, "thread").c_str());
    md += c.quick ? "; **quick** (reduced) sweep.\n" : ".\n";
    md += "> The same figures, machine-readable: [" + c.csvFile + "](" + c.csvFile + ").\n\n";
}

void method(std::string& md, const ReportContext& c) {
    md += "## What is measured\n\n";
    md +=
        "The scene is transformed, rendered in float and in double, and every image is "
        "compared with one reference: the untransformed scene rendered in double at the same "
        "size.\n\n";
    md += "![reference](" + c.referenceFile + ")\n\n";
    md +=
        "- **scale ×10^k**: `scaledScene(scene, 10^k)` multiplies every length (positions, "
        "look_at, radii, checker size); the camera's direction and field of view stay, so "
        "the picture must not change.\n"
        "- **scale ×2^k**: the same with powers of two. These are exact in binary floating "
        "point, so a tracer with no absolute constants (epsilons, offsets, far-away "
        "sentinels) gives the bit-identical image: each is compared bit for bit with the "
        "untransformed render in the same precision.\n"
        "- **move by (1,1,1)·10^k**: `translatedScene(scene, (1,1,1)·10^k)` moves every "
        "position; the offsets are whole numbers, multiples of the checker period 1 "
        "(2 × 0.5), so the pattern is unchanged.\n\n";
    md +=
        "Per point, from `compareImages()` (core/image/image_compare.h, the count the tests and "
        "the editor use): per pixel, the largest channel difference of the sRGB-encoded "
        "display values, where 1/255 is one 8-bit step and a NaN or infinite channel counts "
        "as the largest difference, 1.\n\n"
        "- **> 1/255**, **> 2/255**: share of pixels whose difference exceeds one or two "
        "8-bit steps.\n"
        "- **largest**: the largest difference, in 8-bit steps.\n"
        "- **NaN/Inf**: pixels with a non-finite channel.\n"
        "- **bit-identical** (2^k only): the image equals the same-precision unscaled render "
        "bit for bit.\n"
        "- **time**: the render's wall time (one pass, all samples).\n\n";
    md +=
        "**Bounds**: scale ×10^k keeps at least 99.9% (float) or 99.99% (double) "
        "of pixels within 1/255 of the reference; the offset sweep is held to the same "
        "bounds. This report also requires no NaN or Inf pixel, which the share alone would "
        "let through. Scale ×2^k must be bit-identical. A point whose transformed scene is "
        "not a valid scene (a radius that overflows to infinity or underflows to 0) fails.\n\n"
        "The **range** of a precision is the contiguous run of tested k around k = 0 (from "
        "0 for offsets) in which every point meets the bound. The sweep steps k by 1, "
        "except float ×10^k past ±20 (steps of 5) and double ×10^k past ±40 (steps of 10), "
        "where a range's edge is known only to the step.\n\n";
}

void rangeTable(std::string& md, const std::vector<PointResult>& results,
                const std::vector<RangeSummary>& ranges) {
    md += "## Measured ranges\n\n";
    md +=
        "| sweep | precision | bound | holds for | first failure below / above | issue asks | "
        "met |\n|---|---|---|---|---|---|---|\n";
    for (const RangeSummary& r : ranges) {
        const Ask a = issueAsks(r.kind, r.precision);
        md += "| " + std::string(sweepTitle(r.kind)) + " | " +
              std::string(precisionName(r.precision)) + " | " + boundText(r.kind, r.precision) +
              " | " + kRange(r) + " | " + failures(r) + " | " + askText(r.kind, a) + " | " +
              metText(r, a) + " |\n";
    }
    md += "\n";
    // The offsets' range is asked for but not their bound: state the one that holds over it.
    for (Precision p : {Precision::Float, Precision::Double}) {
        const Ask a = issueAsks(SweepKind::Translate, p);
        const PointResult* worst = nullptr;
        for (const PointResult& r : results)
            if (r.point.kind == SweepKind::Translate && r.point.precision == p && r.point.k >= 2 &&
                r.point.k <= a.high && !r.refused &&
                (!worst || r.fractionOverOne() > worst->fractionOverOne()))
                worst = &r;
        if (!worst) continue;
        md += printed("Offsets of 1e2 to 1e%d in %s: at worst (k = %d) ", a.high,
                      std::string(precisionName(p)).c_str(), worst->point.k);
        md += figures(*worst) + ".\n\n";
    }
}

// Why the ranges end where they do: the design facts behind the numbers above.
void readingNotes(std::string& md) {
    md += "## Why the ranges end there\n\n";
    md +=
        "- **Scale**: the tracer has no absolute constant (no epsilon, offset or far-away "
        "sentinel) and keeps huge spheres as two-term centres and radii, so scaling costs "
        "nothing until squared lengths leave the precision's normal range (float: 1.2e-38 "
        "to 3.4e38; double: 2.2e-308 to 1.8e308). Beyond, the floor's radius squared "
        "overflows, or the smallest lengths' squares lose their digits. The editor warns "
        "when a float scene lies outside the measured float range (core/analysis/float_range.cpp), "
        "and offers to switch to double.\n"
        "- **Offset**: positions are taken relative to the camera, in double, before the "
        "tracer rounds them to its precision, so moving a scene costs only what its own "
        "double coordinates lose: at 1e10 doubles are 2e-6 apart, which shows as a few "
        "pixels on silhouettes. Float and double then fail together, with the same pixels; "
        "the float bound (0.1%) tolerates a few more of them than the double bound (0.01%).\n\n";
}

void pictureSection(std::string& md, const std::vector<Picture>& pictures) {
    md += "## Where it breaks\n\n";
    if (pictures.empty()) {
        md += "No tested point fails.\n\n";
        return;
    }
    md +=
        "The first failing point on each side of every range: the render, and its "
        "difference from the reference as a heat map (black: equal; red, yellow, white: "
        "larger, white from 8/255 on; magenta: NaN or Inf).\n\n";
    for (const Picture& p : pictures) {
        const SweepPoint& pt = p.result.point;
        md += printed("### %s, %s, k = %s (%s)\n\n", std::string(sweepTitle(pt.kind)).c_str(),
                      std::string(precisionName(pt.precision)).c_str(), signedK(pt.k).c_str(),
                      p.side.c_str());
        md += "Transform " + transformLabel(pt) + ": " + figures(p.result) + ".\n\n";
        if (p.imageFile.empty()) continue;
        md += "| render | difference |\n|---|---|\n";
        md += "| ![render](" + p.imageFile + ") | ![difference](" + p.heatFile + ") |\n\n";
    }
}

void pointTables(std::string& md, const std::vector<PointResult>& results,
                 const std::vector<RangeSummary>& ranges) {
    md += "## Every point\n\n";
    for (const RangeSummary& range : ranges) {
        md += "### " + std::string(sweepTitle(range.kind)) + ", " +
              std::string(precisionName(range.precision)) + "\n\n";
        const bool bits = range.kind == SweepKind::Scale2;
        md += "| k | transform | > 1/255 | > 2/255 | largest | NaN/Inf |";
        md += bits ? " bit-identical |" : "";
        md += " time | bound |\n|---:|---|---:|---:|---:|---:|";
        md += bits ? "---|" : "";
        md += "---:|---|\n";
        for (const PointResult& r : results) {
            if (r.point.kind != range.kind || r.point.precision != range.precision) continue;
            md += "| " + signedK(r.point.k) + " | " + transformLabel(r.point) + " | ";
            if (r.refused) {
                md += "refused: " + *r.refused + " | | | |" + (bits ? " |" : "") + " | fails |\n";
                continue;
            }
            md += percent(r.fractionOverOne()) + " | " + percent(r.fractionOverTwo()) + " | " +
                  steps(r.largest) + " | " + printed("%zu", r.nonFinite) + " | ";
            if (bits) md += std::string(r.bitIdentical.value_or(false) ? "yes" : "**no**") + " | ";
            md += printed("%.1f ms", r.seconds * 1e3) + " | " +
                  (meetsBound(r) ? "holds" : "**fails**") + " |\n";
        }
        md += "\n";
    }
}

// Quoted when it holds a comma or a quote (RFC 4180).
std::string csvField(const std::string& s) {
    if (s.find_first_of(",\"\n") == std::string::npos) return s;
    std::string out = "\"";
    for (char c : s) out += c == '"' ? std::string("\"\"") : std::string(1, c);
    return out + "\"";
}

}  // namespace

std::string markdownReport(const ReportContext& context, const std::vector<PointResult>& results,
                           const std::vector<RangeSummary>& ranges,
                           const std::vector<Picture>& pictures) {
    std::string md;
    header(md, context);
    rangeTable(md, results, ranges);
    readingNotes(md);
    method(md, context);
    pictureSection(md, pictures);
    pointTables(md, results, ranges);
    return md;
}

std::string csvReport(const std::vector<PointResult>& results) {
    std::string csv =
        "sweep,precision,k,transform,pixels,over_1_255,over_2_255,fraction_over_1_255,"
        "fraction_over_2_255,largest_difference,nonfinite_pixels,bit_identical,seconds,"
        "meets_bound,refused\n";
    for (const PointResult& r : results) {
        const std::string bits =
            r.bitIdentical ? std::string(*r.bitIdentical ? "yes" : "no") : std::string();
        csv += std::string(sweepId(r.point.kind)) + "," +
               std::string(precisionName(r.point.precision)) + "," + std::to_string(r.point.k) +
               "," + csvField(transformLabel(r.point)) + ",";
        if (r.refused) {
            csv += ",,,,,,,,,no," + csvField(*r.refused) + "\n";
            continue;
        }
        csv += printed("%zu,%zu,%zu,%.9g,%.9g,%.9g,%zu,", r.pixels, r.overOne, r.overTwo,
                       r.fractionOverOne(), r.fractionOverTwo(), double(r.largest), r.nonFinite);
        csv += bits + printed(",%.6f,", r.seconds) + (meetsBound(r) ? "yes" : "no") + ",\n";
    }
    return csv;
}

}  // namespace whitted::numerics
