#include "quality_section.h"

#include <algorithm>
#include <cstdio>
#include <set>
#include <sstream>

#include "tradeoff_report.h"

namespace whitted::tradeoff {

namespace {

std::string targetText(const QualityRow& r) {
    return printed("%.0f dB", r.targetPsnrDb) +
           (r.targetLargestCodes ? printed(", ≤ %.0f codes", *r.targetLargestCodes) : "");
}

std::string measuredText(double psnrDb, double largestCodes, bool met) {
    return printed("%.1f dB, %.0f codes", psnrDb, largestCodes) + (met ? ", met" : ", **missed**");
}

std::string timeText(const QualityRow& r) {
    if (!r.timeAgainstFixedMeeting) return "none up to 256 spp meets it";
    return printed("%.2f", *r.timeAgainstFixedMeeting) + " (" + r.fixedMeeting + ")";
}

void explanation(std::ostream& md) {
    md << "## Rendering to a quality\n\n"
          "The presets above are settings, fitted on these scenes. `whitted-render --quality "
          "draft|preview|final` and the editor's Draft, Preview and Final name the targets "
          "instead, and choose the settings for the scene at hand:\n\n"
          "- **The depth** is measured: the picture at each depth against depth 64, the "
          "deepest SPEC allows, at a small size and then at the picture's own, with samples "
          "where a pixel may hide a sliver of light trapped in glass. The first depth whose "
          "cut is within a tenth of the error the target allows on average, and half its "
          "largest error at any pixel, is taken.\n"
          "- **The precision** is float unless float against double would take more than a "
          "tenth of that error.\n"
          "- **The samples**: each tile is sampled until its estimated error, from its "
          "samples' two halves and what its neighbours show, is under what is left.\n\n"
          "The status bar, its tooltip and `--stats` say what was chosen and why. "
          "[Quality planning](design/quality-planning.md) explains each step, and measures it on "
          "fields "
          "nothing was tuned on.\n\n";
}

void table(std::ostream& md, const std::vector<QualityRow>& rows) {
    md << "| scene | target | chosen: depth, mean samples | measured | fixed preset | "
          "time against a fixed setting that meets the target |\n|---|---|---|---|---|---|\n";
    for (const QualityRow& r : rows)
        md << "| " << r.scene << " | " << r.target << ": " << targetText(r) << " | " << r.depth
           << (r.depthShort ? "*" : "") << ", " << printed("%.1f", r.meanSamples) << " | "
           << measuredText(r.psnrDb, r.largestCodes, r.met) << " | "
           << measuredText(r.presetPsnrDb, r.presetLargestCodes, r.presetMet) << " | "
           << timeText(r) << " |\n";
}

void tally(std::ostream& md, const std::vector<QualityRow>& rows) {
    const auto count = [&](auto test) { return std::count_if(rows.begin(), rows.end(), test); };
    const auto met = count([](const QualityRow& r) { return r.met; });
    const auto psnr = count([](const QualityRow& r) { return r.psnrDb >= r.targetPsnrDb; });
    const auto preset = count([](const QualityRow& r) { return r.presetMet; });
    md << "\nRendered to the target, " << met << " of " << rows.size()
       << " met it, the PSNR and the largest error both; " << psnr << " of " << rows.size()
       << " met the PSNR. The fixed presets met " << preset << " of " << rows.size()
       << ". A depth with * is one the plan said beforehand may not be enough.\n\n";
}

}  // namespace

std::string qualitySection(const std::vector<QualityRow>& rows, const std::string& csvFile) {
    std::ostringstream md;
    explanation(md);
    if (rows.empty()) return md.str();
    std::set<std::string> dates;
    for (const QualityRow& r : rows) dates.insert(r.date);
    md << "Measured on " << *dates.begin() << (dates.size() > 1 ? " to " + *dates.rbegin() : "")
       << " at " << rows.front().width << "x" << rows.front().height
       << ", in float, against a converged render (double, 512 samples a pixel, depth 64), "
          "with `WHITTED_QUALITY_CSV="
       << csvFile << " build/bin/bench_quality " << rows.front().width << " " << rows.front().height
       << "`. The time is ours, planning included, over that of the preset where it meets the "
          "target (the median of pairs of runs), else of the fewest samples a pixel that meet it "
          "at our depth (one run each), in one process. What a user waits for, whole runs "
          "(`benchmarks/whole_run_presets.sh`), is in [quality "
          "planning](design/quality-planning.md): there a Draft's few "
          "milliseconds of planning are a few hundredths of the run.\n\n";
    table(md, rows);
    tally(md, rows);
    return md.str();
}

}  // namespace whitted::tradeoff
