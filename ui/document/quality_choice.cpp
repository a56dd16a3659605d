#include "document/quality_choice.h"

#include <QComboBox>

#include "image/image_error.h"

namespace whitted::ui {

void QualityChoice::setTarget(std::optional<QualityTarget> target) {
    if (target == target_) return;
    target_ = std::move(target);
    if (target_) whitted1980_.reset();
    emit changed();
}

void QualityChoice::setWhitted1980(std::optional<Whitted1980Sampling> sampling) {
    const auto same = [](const auto& a, const auto& b) {
        return a.has_value() == b.has_value() &&
               (!a || (a->threshold == b->threshold && a->maxLevels == b->maxLevels));
    };
    if (same(sampling, whitted1980_)) return;
    whitted1980_ = sampling;
    if (whitted1980_) target_.reset();
    emit changed();
}

void QualityChoice::noteReached(const std::string& targetName, const QString& text) {
    reached_[targetName] = text;
    emit reachedNoted();
}

QString QualityChoice::lastReached(const std::string& targetName) const {
    const auto found = reached_.find(targetName);
    return found == reached_.end() ? QString() : found->second;
}

void QualityChoice::forgetReached() {
    reached_.clear();
    emit reachedNoted();
}

std::vector<QualityTarget> QualityChoice::offered() {
    return {draftQuality(), previewQuality(), finalQuality()};
}

int QualityChoice::indexOf(const std::optional<QualityTarget>& target) {
    const std::vector<QualityTarget> all = offered();
    for (std::size_t i = 0; i < all.size(); ++i)
        if (target == all[i]) return int(i) + 1;
    return 0;
}

QComboBox* QualityChoice::makeComboBox(const QString& objectName,
                                       const std::optional<QualityTarget>& shown) {
    auto* box = new QComboBox;
    box->setObjectName(objectName);
    box->addItem(describe(std::nullopt));
    for (const QualityTarget& t : offered()) box->addItem(describe(t));
    box->setCurrentIndex(indexOf(shown));
    return box;
}

std::optional<QualityTarget> QualityChoice::chosenIn(const QComboBox* box) {
    const int index = box->currentIndex();
    if (index <= 0) return std::nullopt;
    return offered()[std::size_t(index - 1)];
}

QString QualityChoice::describe(const std::optional<QualityTarget>& target) {
    if (!target) return tr("The samples per pixel and max depth set here");
    return QString::fromStdString(describeTarget(*target));
}

QString QualityChoice::samplesPerPixel(int samples) {
    if (samples == 1) return tr("1 sample per pixel");
    return tr("%1 samples per pixel").arg(samples);
}

QString QualityChoice::samplesTaken(const AdaptiveOutcome& reached) {
    if (reached.fewestSamples == reached.mostSamples) return samplesPerPixel(reached.mostSamples);
    return tr("%1 to %2 samples per pixel").arg(reached.fewestSamples).arg(reached.mostSamples);
}

QString QualityChoice::reachedText(const QualityPlan& plan, const AdaptiveOutcome& reached) {
    return tr("depth %1, %2, about %3")
        .arg(plan.maxDepth)
        .arg(samplesTaken(reached))
        .arg(QString::fromStdString(psnrText(estimatedPsnr(plan, reached))));
}

}  // namespace whitted::ui
