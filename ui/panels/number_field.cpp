// Number editors bound to the scene document, and the refused-edit message.
#include "panels/number_field.h"

#include <algorithm>
#include <cmath>

#include <QFontMetrics>
#include <QGuiApplication>
#include <QHBoxLayout>
#include <QKeyEvent>
#include <QLineEdit>
#include <QLocale>
#include <QMessageBox>
#include <QSignalBlocker>
#include <QWheelEvent>

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

// Sets `flag` for the lifetime of the scope: the Shift of the event being handled.
class FineScope {
  public:
    FineScope(bool& flag, Qt::KeyboardModifiers modifiers) : flag_(flag) {
        flag_ = modifiers.testFlag(Qt::ShiftModifier);
    }
    ~FineScope() { flag_ = false; }
    FineScope(const FineScope&) = delete;
    FineScope& operator=(const FineScope&) = delete;

  private:
    bool& flag_;
};

// A slider whose arrow keys and wheel move one position, its finest, while
// Shift is held. (QSlider's own wheel jumps a page on Shift.)
class FineSlider : public QSlider {
  public:
    using QSlider::QSlider;

  protected:
    void keyPressEvent(QKeyEvent* event) override {
        if (!event->modifiers().testFlag(Qt::ShiftModifier)) return QSlider::keyPressEvent(event);
        const int coarse = singleStep();
        setSingleStep(1);
        QSlider::keyPressEvent(event);
        setSingleStep(coarse);
    }
    void wheelEvent(QWheelEvent* event) override {
        if (!event->modifiers().testFlag(Qt::ShiftModifier)) return QSlider::wheelEvent(event);
        // Some platforms turn a Shift+wheel into a horizontal one.
        const QPoint delta = event->angleDelta();
        const int turn = delta.y() != 0 ? delta.y() : delta.x();
        if (turn == 0) return event->ignore();
        const int direction = (turn > 0) != invertedControls() ? 1 : -1;
        setValue(value() + direction);
        event->accept();
    }
};

// A logarithmic slider has this many positions per decade: one position is a
// 0.58 % change, one arrow step (kLogSingleStep positions) 4.7 %, whatever the
// value, so a 0.05 marble's radius moves as finely as a 5-unit ball's.
constexpr int kLogPositionsPerDecade = 400;
constexpr int kLogSingleStep = 8;
// A linear slider: 1000 positions, an arrow step being 1 % of its range.
constexpr int kLinearPositions = 1000;

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
    // The spin box's auto-repeat steps from a timer, with no event to ask.
    const bool fine = fine_ || QGuiApplication::keyboardModifiers().testFlag(Qt::ShiftModifier);
    if (fine) {
        stepped = std::clamp(value() + steps * stepSize(steps) / 10.0, minimum(), maximum());
    } else {
        const QSignalBlocker block(this);
        const double before = value();
        QDoubleSpinBox::stepBy(steps);
        stepped = value();
        setValue(before);
    }
    setValue(QString::number(stepped, 'g', 15).toDouble());
}

// Qt's step: the single step, or with adaptive steps a tenth of the value's
// power of ten (a step down from 1 is 0.01, Qt's rule of thumb).
double NumberSpinBox::stepSize(int steps) const {
    if (stepType() != AdaptiveDecimalStepType) return singleStep();
    double magnitude = std::abs(value());
    if (magnitude == 0.0) return singleStep();
    if ((value() < 0) != (steps < 0)) magnitude /= 1.01;
    return std::pow(10.0, std::floor(std::log10(magnitude)) - 1.0);
}

void NumberSpinBox::keyPressEvent(QKeyEvent* event) {
    const FineScope scope(fine_, event->modifiers());
    QDoubleSpinBox::keyPressEvent(event);
}

void NumberSpinBox::wheelEvent(QWheelEvent* event) {
    const FineScope scope(fine_, event->modifiers());
    QDoubleSpinBox::wheelEvent(event);
}

void NumberSpinBox::mousePressEvent(QMouseEvent* event) {
    const FineScope scope(fine_, event->modifiers());
    QDoubleSpinBox::mousePressEvent(event);
}

void NumberSpinBox::setMixed(bool mixed) {
    if (mixed == mixed_) return;
    mixed_ = mixed;
    lineEdit()->setPlaceholderText(mixed ? tr("mixed") : QString());
    lineEdit()->setText(mixed ? QString() : prefix() + textFromValue(value()) + suffix());
}

QString NumberSpinBox::textFromValue(double value) const {
    if (mixed_) return {};
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
                         Getter get, Commit edit, TextFn undoText, QWidget* parent)
    : QWidget(parent),
      doc_(doc),
      spec_(spec),
      get_(std::move(get)),
      commit_(std::move(edit)),
      undoText_(std::move(undoText)),
      spin_(new NumberSpinBox(this)) {
    setObjectName(objectName + QStringLiteral("Field"));
    spin_->setObjectName(objectName);
    spin_->setRange(spec.min, spec.max);
    spin_->setSingleStep(spec.step);
    if (spec.adaptiveStep && !spec.stepOf)
        spin_->setStepType(QAbstractSpinBox::AdaptiveDecimalStepType);
    spin_->setSuffix(spec.suffix);

    auto* layout = new QHBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addWidget(spin_, 2);
    connect(spin_, &QDoubleSpinBox::valueChanged, this, &DoubleField::commit);

    if (spec.slider != SliderScale::None) {
        slider_ = new FineSlider(Qt::Horizontal, this);
        slider_->setObjectName(objectName + QStringLiteral("Slider"));
        slider_->setRange(0, sliderSteps());
        const int single = spec.slider == SliderScale::Log ? kLogSingleStep : sliderSteps() / 100;
        slider_->setSingleStep(single);
        slider_->setPageStep(single * 10);
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

int DoubleField::sliderSteps() const {
    if (spec_.slider != SliderScale::Log) return kLinearPositions;
    const double decades = std::log10(spec_.sliderMax / spec_.sliderMin);
    return std::max(1, static_cast<int>(std::lround(decades * kLogPositionsPerDecade)));
}

double DoubleField::sliderToValue(int position) const {
    const double t = static_cast<double>(position) / sliderSteps();
    double value;
    if (spec_.slider == SliderScale::Log)
        value = std::exp(std::log(spec_.sliderMin) +
                         t * (std::log(spec_.sliderMax) - std::log(spec_.sliderMin)));
    else
        value = spec_.sliderMin + t * (spec_.sliderMax - spec_.sliderMin);
    return roundForSlider(value, spec_, sliderSteps());
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
    return static_cast<int>(std::lround(std::clamp(t, 0.0, 1.0) * sliderSteps()));
}

void DoubleField::refresh() {
    if (!doc_) return;
    const double value = get_(doc_->scene());
    if (spec_.stepOf) spin_->setSingleStep(spec_.stepOf(doc_->scene()));
    {
        const QSignalBlocker block(spin_);
        spin_->setMixed(mixedOf_ && mixedOf_(doc_->scene()));
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
    if (commit_(*doc_, undoText_(), value, &error)) return;
    showRefusal(this, error);
    refresh();
}

DoubleField::Commit sceneCommit(std::function<void(Scene&, double)> set) {
    return [set = std::move(set)](SceneDocument& doc, const QString& text, double value,
                                  QString* error) {
        return doc.edit(
            text, [&](Scene& scene) { set(scene, value); }, error);
    };
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
        if (!editOrTell(this, doc_, undoText_(), [&](Scene& scene) { set_(scene, value); }))
            refresh();
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

bool editOrTell(QWidget* from, SceneDocument* doc, const QString& text,
                const std::function<void(Scene&)>& change) {
    QString error;
    if (doc->edit(text, change, &error)) return true;
    showRefusal(from, error);
    return false;
}

}  // namespace whitted::ui
