// Number editors bound to the scene document, and the refused-edit message.
#include "number_field.h"

#include <algorithm>
#include <cmath>

#include <QFontMetrics>
#include <QHBoxLayout>
#include <QLineEdit>
#include <QLocale>
#include <QMessageBox>
#include <QSignalBlocker>

namespace whitted::ui {

namespace {

// QDoubleSpinBox rounds every value to `decimals` places; its largest setting
// (DBL_MAX_10_EXP + DBL_DIG) rounds nothing a double can hold, so a radius of
// 5e-21 from a file (the seed scaled to the edge of float's range) stays 5e-21
// rather than showing, and being saved back, as 0.
constexpr int kDecimals = 323;

QLocale displayLocale(const QLocale& base) {
    QLocale locale = base;
    locale.setNumberOptions(QLocale::OmitGroupSeparator);
    return locale;
}

// A slider value as a user would type it: to the slider's resolution when linear,
// to three significant digits when logarithmic, so a drag does not write
// 0.61234567 into the scene file.
double roundForSlider(double value, const DoubleFieldSpec& spec, int steps) {
    if (value == 0.0 || !std::isfinite(value)) return value;
    double quantum;
    if (spec.slider == SliderScale::Log) {
        quantum = std::pow(10.0, std::floor(std::log10(std::abs(value))) - 2.0);
    } else {
        const double resolution = (spec.sliderMax - spec.sliderMin) / steps;
        quantum = std::pow(10.0, std::floor(std::log10(resolution)));
    }
    // Dividing by a power of ten (rather than multiplying by its inexact inverse)
    // gives the double nearest the decimal, whose shortest text is the decimal.
    if (quantum < 1.0) {
        const double scale = std::round(1.0 / quantum);
        return std::round(value * scale) / scale;
    }
    return std::round(value / quantum) * quantum;
}

}  // namespace

NumberSpinBox::NumberSpinBox(QWidget* parent) : QDoubleSpinBox(parent) {
    setDecimals(kDecimals);
    setKeyboardTracking(false);
    setAccelerated(true);
}

// Stepping adds binary fractions (0.1 + 0.2 is 0.30000000000000004), noise the
// 323 decimals no longer round away: the stepped value keeps 15 significant
// digits, all a double holds for sure. The base class steps (adaptive step
// sizes included) with signals blocked, so the field sees one change.
void NumberSpinBox::stepBy(int steps) {
    double stepped;
    {
        const QSignalBlocker block(this);
        const double before = value();
        QDoubleSpinBox::stepBy(steps);
        stepped = value();
        setValue(before);
    }
    setValue(QString::number(stepped, 'g', 15).toDouble());
}

QString NumberSpinBox::textFromValue(double value) const {
    const QLocale locale = displayLocale(this->locale());
    const double magnitude = std::abs(value);
    if (magnitude == 0.0) return locale.toString(0);
    if (magnitude >= 1e-4 && magnitude < 1e15)
        return locale.toString(value, 'f', QLocale::FloatingPointShortest);
    return locale.toString(value, 'g', QLocale::FloatingPointShortest);
}

bool NumberSpinBox::parse(QString text, double* value) const {
    if (!prefix().isEmpty() && text.startsWith(prefix())) text.remove(0, prefix().size());
    if (!suffix().isEmpty() && text.endsWith(suffix())) text.chop(suffix().size());
    text = text.trimmed();
    if (text.isEmpty()) return false;
    bool ok = false;
    double parsed = displayLocale(locale()).toDouble(text, &ok);
    if (!ok) parsed = QLocale::c().toDouble(text, &ok);
    if (!ok || !std::isfinite(parsed)) return false;
    *value = parsed;
    return true;
}

double NumberSpinBox::valueFromText(const QString& text) const {
    double parsed = value();
    parse(text, &parsed);
    return parsed;
}

QValidator::State NumberSpinBox::validate(QString& text, int&) const {
    double parsed;
    if (parse(text, &parsed))
        return parsed >= minimum() && parsed <= maximum() ? QValidator::Acceptable
                                                          : QValidator::Intermediate;
    // Half-typed numbers ("-", "1e", "2.") must stay editable.
    const QLocale locale = this->locale();
    const QString allowed = QStringLiteral("0123456789+-eE.,") + locale.decimalPoint() +
                            locale.negativeSign() + locale.exponential() + prefix() + suffix();
    for (const QChar c : text)
        if (!allowed.contains(c) && !c.isSpace()) return QValidator::Invalid;
    return QValidator::Intermediate;
}

void NumberSpinBox::fixup(QString& text) const {
    // An out-of-range number is clamped rather than thrown away.
    double parsed;
    if (parse(text, &parsed))
        text = prefix() + textFromValue(std::clamp(parsed, minimum(), maximum())) + suffix();
}

QSize NumberSpinBox::sizeHint() const {
    // The default hint is the width of the range's ends at full precision, far wider
    // than the values people type; size for a typical number and let it scroll.
    QSize hint = QDoubleSpinBox::sizeHint();
    const QFontMetrics metrics(font());
    const int wanted = metrics.horizontalAdvance(prefix() + QStringLiteral("-0000.000") + suffix());
    const int text = metrics.horizontalAdvance(prefix() + textFromValue(maximum()) + suffix());
    hint.setWidth(hint.width() - std::max(0, text - wanted));
    return hint;
}

QSize NumberSpinBox::minimumSizeHint() const {
    QSize hint = QDoubleSpinBox::minimumSizeHint();
    hint.setWidth(std::min(hint.width(), sizeHint().width() * 2 / 3));
    return hint;
}

DoubleField::DoubleField(SceneDocument* doc, const QString& objectName, const DoubleFieldSpec& spec,
                         Getter get, Setter set, TextFn undoText, QWidget* parent)
    : QWidget(parent),
      doc_(doc),
      spec_(spec),
      get_(std::move(get)),
      set_(std::move(set)),
      undoText_(std::move(undoText)),
      spin_(new NumberSpinBox(this)) {
    setObjectName(objectName + QStringLiteral("Field"));
    spin_->setObjectName(objectName);
    spin_->setRange(spec.min, spec.max);
    spin_->setSingleStep(spec.step);
    if (spec.adaptiveStep) spin_->setStepType(QAbstractSpinBox::AdaptiveDecimalStepType);
    spin_->setSuffix(spec.suffix);

    auto* layout = new QHBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addWidget(spin_, 2);
    connect(spin_, &QDoubleSpinBox::valueChanged, this, &DoubleField::commit);

    if (spec.slider != SliderScale::None) {
        slider_ = new QSlider(Qt::Horizontal, this);
        slider_->setObjectName(objectName + QStringLiteral("Slider"));
        slider_->setRange(0, kSliderSteps);
        slider_->setSingleStep(kSliderSteps / 100);
        slider_->setPageStep(kSliderSteps / 10);
        layout->addWidget(slider_, 3);
        connect(slider_, &QSlider::sliderPressed, this, [this] {
            if (!doc_ || gestureOpen_) return;
            doc_->beginGesture(undoText_());
            gestureOpen_ = true;
        });
        connect(slider_, &QSlider::sliderReleased, this, &DoubleField::endGestureIfOpen);
        connect(slider_, &QSlider::valueChanged, this, [this](int position) {
            const double value = std::clamp(sliderToValue(position), spec_.min, spec_.max);
            {
                const QSignalBlocker block(spin_);
                spin_->setValue(value);
            }
            commit(value);
        });
    }
}

DoubleField::~DoubleField() {
    endGestureIfOpen();
}

void DoubleField::hideEvent(QHideEvent* event) {
    // A hidden slider never sees its mouse release; an open gesture would swallow
    // every later edit into one undo step.
    endGestureIfOpen();
    QWidget::hideEvent(event);
}

void DoubleField::endGestureIfOpen() {
    if (!gestureOpen_) return;
    gestureOpen_ = false;
    if (doc_) doc_->endGesture();
}

double DoubleField::sliderToValue(int position) const {
    const double t = static_cast<double>(position) / kSliderSteps;
    double value;
    if (spec_.slider == SliderScale::Log)
        value = std::exp(std::log(spec_.sliderMin) +
                         t * (std::log(spec_.sliderMax) - std::log(spec_.sliderMin)));
    else
        value = spec_.sliderMin + t * (spec_.sliderMax - spec_.sliderMin);
    return roundForSlider(value, spec_, kSliderSteps);
}

int DoubleField::valueToSlider(double value) const {
    double t;
    if (spec_.slider == SliderScale::Log)
        t = value > 0.0 ? (std::log(value) - std::log(spec_.sliderMin)) /
                              (std::log(spec_.sliderMax) - std::log(spec_.sliderMin))
                        : 0.0;
    else
        t = (value - spec_.sliderMin) / (spec_.sliderMax - spec_.sliderMin);
    if (!std::isfinite(t)) t = 0.0;
    return static_cast<int>(std::lround(std::clamp(t, 0.0, 1.0) * kSliderSteps));
}

void DoubleField::refresh() {
    if (!doc_) return;
    const double value = get_(doc_->scene());
    {
        const QSignalBlocker block(spin_);
        spin_->setValue(value);
    }
    // Moving the handle under the user's mouse would make it jump during a drag.
    if (slider_ && !slider_->isSliderDown()) {
        const QSignalBlocker block(slider_);
        slider_->setValue(valueToSlider(value));
    }
}

void DoubleField::commit(double value) {
    if (!doc_) return;
    QString error;
    if (!doc_->edit(
            undoText_(), [&](Scene& scene) { set_(scene, value); }, &error)) {
        showRefusal(this, error);
        refresh();
    }
}

IntField::IntField(SceneDocument* doc, const QString& objectName, int min, int max, Getter get,
                   Setter set, TextFn undoText, QWidget* parent)
    : QSpinBox(parent),
      doc_(doc),
      get_(std::move(get)),
      set_(std::move(set)),
      undoText_(std::move(undoText)) {
    setObjectName(objectName);
    setRange(min, max);
    setKeyboardTracking(false);
    setAccelerated(true);
    connect(this, &QSpinBox::valueChanged, this, [this](int value) {
        QString error;
        if (!doc_->edit(
                undoText_(), [&](Scene& scene) { set_(scene, value); }, &error)) {
            showRefusal(this, error);
            refresh();
        }
    });
}

void IntField::refresh() {
    const QSignalBlocker block(this);
    setValue(get_(doc_->scene()));
}

void showRefusal(QWidget* parent, const QString& reason) {
    QWidget* window = parent ? parent->window() : nullptr;
    const QString name = QStringLiteral("editRefusedMessage");
    if (window) {
        if (auto* open = window->findChild<QMessageBox*>(name); open && open->isVisible()) {
            open->setText(reason);
            return;
        }
    }
    auto* box = new QMessageBox(QMessageBox::Warning, QObject::tr("Edit refused"), reason,
                                QMessageBox::Ok, window);
    box->setObjectName(name);
    box->setAttribute(Qt::WA_DeleteOnClose);
    box->open();
}

}  // namespace whitted::ui
