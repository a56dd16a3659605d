#include "panels/sampler_controls.h"

#include <QComboBox>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QSignalBlocker>
#include <QSpinBox>

#include "document/quality_choice.h"

namespace whitted::ui {

void addSamplerRows(QFormLayout* form, QualityChoice* quality) {
    auto* sampler = new QComboBox;
    sampler->setObjectName(QStringLiteral("renderSampler"));
    sampler->addItem(QObject::tr("Samples per pixel"));
    sampler->addItem(QObject::tr("Whitted 1980: corners, cut where they differ"));
    sampler->setToolTip(
        QObject::tr("Whitted's adaptive antialiasing (1980): a ray through each pixel corner, "
                    "shared by the pixels that meet there; a pixel whose corners differ by more "
                    "than the threshold is cut in four, and so on down to the subdivisions "
                    "allowed. View > Subdivision Map shows how deep each pixel was cut."));
    auto* threshold = new QDoubleSpinBox;
    threshold->setObjectName(QStringLiteral("samplerThreshold"));
    threshold->setRange(0.0, 255.0);
    threshold->setDecimals(1);
    threshold->setSuffix(QObject::tr(" codes"));
    threshold->setToolTip(
        QObject::tr("Cut a pixel where two of its corners differ by more than "
                    "this, in 8-bit codes of any channel"));
    auto* subdivisions = new QSpinBox;
    subdivisions->setObjectName(QStringLiteral("samplerSubdivisions"));
    subdivisions->setRange(0, kMaxWhitted1980Levels);
    subdivisions->setToolTip(
        QObject::tr("How many times a pixel may be cut in four: at most 4^n cells"));
    const Whitted1980Sampling defaults;
    threshold->setValue(defaults.threshold);
    subdivisions->setValue(defaults.maxLevels);
    // Under the samples per pixel, which it replaces when chosen.
    int row = form->rowCount() - 1;
    QFormLayout::ItemRole role;
    if (QWidget* samples = form->parentWidget()->findChild<QWidget*>("renderSamples"))
        form->getWidgetPosition(samples, &row, &role);
    form->insertRow(row + 1, QObject::tr("Antialiasing:"), sampler);
    form->insertRow(row + 2, QObject::tr("Threshold:"), threshold);
    form->insertRow(row + 3, QObject::tr("Subdivisions:"), subdivisions);

    const auto choose = [=] {
        if (sampler->currentIndex() == 0)
            quality->setWhitted1980(std::nullopt);
        else
            quality->setWhitted1980(Whitted1980Sampling{threshold->value(), subdivisions->value()});
    };
    QObject::connect(sampler, &QComboBox::currentIndexChanged, sampler, choose);
    QObject::connect(threshold, &QDoubleSpinBox::valueChanged, sampler, choose);
    QObject::connect(subdivisions, &QSpinBox::valueChanged, sampler, choose);
    // A target chosen elsewhere (the presets, Render to) sets the sampler back.
    const auto follow = [=] {
        const bool on = quality->whitted1980().has_value();
        const QSignalBlocker quiet(sampler);
        sampler->setCurrentIndex(on ? 1 : 0);
        form->setRowVisible(threshold, on);
        form->setRowVisible(subdivisions, on);
    };
    QObject::connect(quality, &QualityChoice::changed, sampler, follow);
    follow();
}

}  // namespace whitted::ui
