// Number editors bound to one value of the scene: spin boxes (with an optional
// slider) that turn user changes into SceneDocument edits, a slider drag being a
// single undo step, and the shared way of telling the user an edit was refused.
#pragma once

#include <functional>
#include <vector>

#include <QDoubleSpinBox>
#include <QPointer>
#include <QSlider>
#include <QSpinBox>
#include <QString>
#include <QWidget>

#include "document/scene_document.h"
#include "scene/scene.h"

namespace whitted::ui {

// Shows a double in its shortest round-trip form ("0.6", "99999.5", "1e-06")
// rather than with a fixed number of decimals, so values from a file appear as
// written and very small radii do not show as 0. Accepts exponent notation.
class NumberSpinBox : public QDoubleSpinBox {
    Q_OBJECT
  public:
    explicit NumberSpinBox(QWidget* parent = nullptr);

    QSize sizeHint() const override;
    QSize minimumSizeHint() const override;
    // Holding Shift steps by a tenth of the usual step (arrows, keys and wheel).
    void stepBy(int steps) override;
    // Shows no number but "mixed" (the selected items' values differ) until
    // the user types one.
    void setMixed(bool mixed);
    bool mixed() const { return mixed_; }

  protected:
    void keyPressEvent(QKeyEvent* event) override;
    void wheelEvent(QWheelEvent* event) override;
    void mousePressEvent(QMouseEvent* event) override;
    QString textFromValue(double value) const override;
    double valueFromText(const QString& text) const override;
    QValidator::State validate(QString& text, int& pos) const override;
    void fixup(QString& text) const override;

  private:
    bool parse(QString text, double* value) const;
    double stepSize(int steps) const;  // the unmodified step from the current value

    bool fine_ = false;  // the event being handled holds Shift
    bool mixed_ = false;
};

enum class SliderScale { None, Linear, Log };

// Range, step and slider of a DoubleField, built as
// DoubleFieldSpec::range(0, 1, 0.05).linearSlider(0, 1).
struct DoubleFieldSpec {
    double min = 0.0;
    double max = 1.0;
    double step = 0.1;
    bool adaptiveStep = false;  // step by a tenth of the value's order of magnitude
    SliderScale slider = SliderScale::None;
    double sliderMin = 0.0;  // the slider's end values; the spin box may go beyond them
    double sliderMax = 1.0;
    QString suffix;  // unit, e.g. " °"
    // The spin box's step, re-read from the scene on refresh (a sphere's centre
    // steps by a tenth of its radius); overrides `step` and `adaptiveStep`.
    std::function<double(const Scene&)> stepOf;

    static DoubleFieldSpec range(double min, double max, double step) {
        DoubleFieldSpec spec;
        spec.min = min;
        spec.max = max;
        spec.step = step;
        return spec;
    }
    DoubleFieldSpec adaptive() const {
        DoubleFieldSpec spec = *this;
        spec.adaptiveStep = true;
        return spec;
    }
    DoubleFieldSpec linearSlider(double from, double to) const {
        return withSlider(SliderScale::Linear, from, to);
    }
    DoubleFieldSpec logSlider(double from, double to) const {
        return withSlider(SliderScale::Log, from, to);
    }
    DoubleFieldSpec stepFrom(std::function<double(const Scene&)> fn) const {
        DoubleFieldSpec spec = *this;
        spec.stepOf = std::move(fn);
        return spec;
    }
    DoubleFieldSpec unit(const QString& text) const {
        DoubleFieldSpec spec = *this;
        spec.suffix = text;
        return spec;
    }

  private:
    DoubleFieldSpec withSlider(SliderScale scale, double from, double to) const {
        DoubleFieldSpec spec = *this;
        spec.slider = scale;
        spec.sliderMin = from;
        spec.sliderMax = to;
        return spec;
    }
};

// A spin box, and a slider when the spec asks for one, editing one double of the
// scene. `get` is only called by refresh(); `edit` makes the edit (sceneCommit()
// for a whole-scene edit, or an item edit) and must change nothing when its item
// no longer exists. `undoText` names the step ("Change radius of ball").
class DoubleField : public QWidget {
    Q_OBJECT
  public:
    using Getter = std::function<double(const Scene&)>;
    // Puts `value` into the document as one edit named `text`; false, with the
    // reason in `error`, when the document refuses it.
    using Commit =
        std::function<bool(SceneDocument& doc, const QString& text, double value, QString* error)>;
    using TextFn = std::function<QString()>;

    DoubleField(SceneDocument* doc, const QString& objectName, const DoubleFieldSpec& spec,
                Getter get, Commit edit, TextFn undoText, QWidget* parent = nullptr);
    ~DoubleField() override;

    // Shows the scene's value; emits nothing.
    void refresh();
    // Whether the items the field edits hold different values ("mixed").
    void setMixedOf(std::function<bool(const Scene&)> mixed) { mixedOf_ = std::move(mixed); }

    NumberSpinBox* spinBox() const { return spin_; }
    QSlider* slider() const { return slider_; }  // nullptr without one

  protected:
    void hideEvent(QHideEvent* event) override;

  private:
    int sliderSteps() const;
    double sliderToValue(int position) const;
    int valueToSlider(double value) const;
    void commit(double value);
    void endGestureIfOpen();

    QPointer<SceneDocument> doc_;
    DoubleFieldSpec spec_;
    Getter get_;
    Commit commit_;
    TextFn undoText_;
    std::function<bool(const Scene&)> mixedOf_;
    NumberSpinBox* spin_;
    QSlider* slider_ = nullptr;
    bool gestureOpen_ = false;
};

// A DoubleField's commit for a value anywhere in the scene: SceneDocument::edit
// of a copy that `set` changes.
DoubleField::Commit sceneCommit(std::function<void(Scene&, double)> set);

// A spin box editing one int of the scene; same contract as DoubleField.
class IntField : public QSpinBox {
    Q_OBJECT
  public:
    using Getter = std::function<int(const Scene&)>;
    using Setter = std::function<void(Scene&, int)>;
    using TextFn = std::function<QString()>;

    IntField(SceneDocument* doc, const QString& objectName, int min, int max, Getter get,
             Setter set, TextFn undoText, QWidget* parent = nullptr);

    void refresh();

  private:
    SceneDocument* doc_;
    Getter get_;
    Setter set_;
    TextFn undoText_;
};

// Tells the user why an edit was refused. The box is window-modal but opened
// without a nested event loop, so a refused edit never blocks the caller (or a
// test); a second refusal while it is open replaces its text.
void showRefusal(QWidget* parent, const QString& reason);

// Makes one edit; a refusal is shown to the user over `from`. True when made.
bool editOrTell(QWidget* from, SceneDocument* doc, const QString& text,
                const std::function<void(Scene&)>& change);

// The same for one change to several items of a list (SceneDocument::editItems).
template <class T>
bool editItemsOrTell(QWidget* from, SceneDocument* doc, const std::vector<int>& indices,
                     const QString& text, const std::function<void(T&)>& change) {
    QString error;
    if (doc->editItems<T>(
            indices, text, [&](T& item, int) { change(item); }, &error))
        return true;
    showRefusal(from, error);
    return false;
}

}  // namespace whitted::ui
