#include "panels/image_size_fields.h"

#include <QCheckBox>
#include <QComboBox>
#include <QGridLayout>
#include <QLabel>
#include <QSignalBlocker>
#include <QSpinBox>

#include <algorithm>
#include <cmath>
#include <numeric>

#include "document/scene_document.h"
#include "scene/scene.h"

namespace whitted::ui {

const std::vector<CommonSize>& commonSizes() {
    static const std::vector<CommonSize> sizes = {
        {"VGA", 640, 480},           {"SVGA", 800, 600},
        {"HD 720p", 1280, 720},      {"Full HD", 1920, 1080},
        {"QHD", 2560, 1440},         {"4K UHD", 3840, 2160},
        {"Square", 1024, 1024},      {"Square large", 2048, 2048},
        {"Portrait HD", 1080, 1920}, {"A4 poster at 150 dpi", 1240, 1754},
    };
    return sizes;
}

QString sizeText(int width, int height) {
    const int g = std::gcd(width, height);
    const int aw = width / g, ah = height / g;
    // Ratios like 1240:1754 say less than a decimal.
    const QString ratio = aw <= 32 && ah <= 32 ? QStringLiteral("%1:%2").arg(aw).arg(ah)
                                               : QString::number(double(width) / height, 'f', 2);
    return QStringLiteral("%1 × %2 (%3)").arg(width).arg(height).arg(ratio);
}

namespace {

void fillCommonSizes(QComboBox* combo, const QString& first) {
    combo->addItem(first);
    for (const CommonSize& s : commonSizes())
        combo->addItem(
            QStringLiteral("%1: %2").arg(QObject::tr(s.name), sizeText(s.width, s.height)),
            QSize(s.width, s.height));
}

}  // namespace

QComboBox* makeCommonSizeChooser(SceneDocument* doc, QWidget* parent) {
    auto* combo = new QComboBox(parent);
    combo->setObjectName(QStringLiteral("renderCommonSize"));
    combo->setToolTip(QObject::tr(
        "Sets width and height to a common size; the view then frames what an export at "
        "that size will show"));
    fillCommonSizes(combo, QObject::tr("Choose a common size…"));
    QObject::connect(combo, &QComboBox::activated, combo, [doc, combo](int index) {
        const QSize size = combo->itemData(index).toSize();
        combo->setCurrentIndex(0);
        if (size.isEmpty()) return;
        doc->edit(QObject::tr("Set image size to %1").arg(sizeText(size.width(), size.height())),
                  [size](Scene& s) {
                      s.render.width = size.width();
                      s.render.height = size.height();
                  });
    });
    return combo;
}

ImageSizeFields::ImageSizeFields(int sceneWidth, int sceneHeight, const QString& prefix,
                                 QWidget* parent)
    : QWidget(parent), sceneAspect_(double(sceneWidth) / sceneHeight) {
    auto spin = [&](const QString& name, int value) {
        auto* s = new QSpinBox;
        s->setObjectName(prefix + name);
        s->setRange(1, kMaxImageSize);
        s->setValue(value);
        s->setSuffix(tr(" px"));
        return s;
    };
    width_ = spin(QStringLiteral("Width"), sceneWidth);
    height_ = spin(QStringLiteral("Height"), sceneHeight);
    lock_ = new QCheckBox(
        tr("Keep the scene's aspect ratio, %1").arg(sizeText(sceneWidth, sceneHeight)));
    lock_->setObjectName(prefix + QStringLiteral("AspectLock"));
    lock_->setChecked(true);
    lock_->setToolTip(tr("Keep width and height in the scene's aspect ratio (%1), so the image "
                         "is framed as the view shows it")
                          .arg(sizeText(sceneWidth, sceneHeight)));
    common_ = new QComboBox;
    common_->setObjectName(prefix + QStringLiteral("CommonSize"));
    fillCommonSizes(common_, tr("Common sizes…"));
    note_ = new QLabel;
    note_->setObjectName(prefix + QStringLiteral("AspectNote"));
    note_->setWordWrap(true);

    auto* grid = new QGridLayout(this);
    grid->setContentsMargins(0, 0, 0, 0);
    grid->addWidget(new QLabel(tr("Width")), 0, 0);
    grid->addWidget(width_, 0, 1);
    grid->addWidget(new QLabel(tr("Height")), 1, 0);
    grid->addWidget(height_, 1, 1);
    grid->addWidget(lock_, 2, 0, 1, 2);
    grid->addWidget(common_, 3, 0, 1, 2);
    grid->addWidget(note_, 4, 0, 1, 2);

    connect(width_, &QSpinBox::valueChanged, this, &ImageSizeFields::widthChanged);
    connect(height_, &QSpinBox::valueChanged, this, &ImageSizeFields::heightChanged);
    connect(lock_, &QCheckBox::toggled, this, [this](bool locked) {
        if (locked) widthChanged(width_->value());
        updateNote();
    });
    connect(common_, &QComboBox::activated, this, &ImageSizeFields::commonSizeChosen);
    updateNote();
}

int ImageSizeFields::imageWidth() const {
    return width_->value();
}
int ImageSizeFields::imageHeight() const {
    return height_->value();
}
bool ImageSizeFields::aspectLocked() const {
    return lock_->isChecked();
}

void ImageSizeFields::widthChanged(int width) {
    if (lock_->isChecked()) {
        const QSignalBlocker block(height_);
        height_->setValue(std::clamp(int(std::lround(width / sceneAspect_)), 1, kMaxImageSize));
    }
    updateNote();
}

void ImageSizeFields::heightChanged(int height) {
    if (lock_->isChecked()) {
        const QSignalBlocker block(width_);
        width_->setValue(std::clamp(int(std::lround(height * sceneAspect_)), 1, kMaxImageSize));
    }
    updateNote();
}

void ImageSizeFields::commonSizeChosen(int index) {
    const QSize size = common_->itemData(index).toSize();
    common_->setCurrentIndex(0);
    if (size.isEmpty()) return;
    // A size of another aspect is what the user asked for: unlock rather than bend it.
    if (std::abs(double(size.width()) / size.height() - sceneAspect_) > 0.01)
        lock_->setChecked(false);
    const QSignalBlocker blockW(width_), blockH(height_);
    width_->setValue(size.width());
    height_->setValue(size.height());
    updateNote();
}

void ImageSizeFields::updateNote() {
    const double aspect = double(width_->value()) / height_->value();
    // Within one pixel of rounding the framing is the same.
    const bool differs = std::abs(aspect - sceneAspect_) * height_->value() > 1.0;
    note_->setVisible(differs);
    if (differs)
        note_->setText(tr("⚠ This image is %1 wide for its height, the scene's view %2: the "
                          "picture will be framed differently from the view (the vertical "
                          "field of view is kept, so the sides are cut or extended).")
                           .arg(aspect, 0, 'f', 2)
                           .arg(sceneAspect_, 0, 'f', 2));
}

}  // namespace whitted::ui
