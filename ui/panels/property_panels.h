// Property editors: the selected sphere, light or material, the camera, and the
// render settings. Each re-reads the scene on every change (undo and redo
// included) and turns user input into one SceneDocument edit.
#pragma once

#include <functional>
#include <vector>

#include <QWidget>

#include "document/scene_document.h"
#include "scene/scene_fields.h"

class QComboBox;
class QFormLayout;
class QLabel;
class QStackedWidget;

namespace whitted::ui {

class ColorButton;
class QualityChoice;
class DoubleField;
class IntField;
class MaterialPage;
class SpherePage;

class PropertyPanel : public QWidget {
    Q_OBJECT
  public:
    // Shows the document's selection: its active item's page, editing every
    // selected item; nothing selected, the empty page.
    explicit PropertyPanel(SceneDocument* doc, QWidget* parent = nullptr);

  private:
    ItemKind kind() const { return doc_->selection()->kind(); }
    int index() const { return doc_->selection()->active(); }
    QWidget* buildLightPage();
    void refresh();
    bool valid() const;
    QString itemLabel() const;  // the shown item's name, for undo texts
    // An undo text "<verb> <what> of <item>"; the item name is read when the edit happens.
    std::function<QString()> changeText(const QString& what) const;
    void editLight(const QString& what, const std::function<void(Light&)>& change);

    SceneDocument* doc_;
    QStackedWidget* pages_;
    QWidget* emptyPage_;
    SpherePage* spherePage_;
    QWidget* lightPage_;
    MaterialPage* materialPage_;
    QLabel* lightName_;
    ColorButton* lightColor_;
    std::vector<DoubleField*> lightFields_;
};

// The camera: position, look-at point, up vector and vertical field of view.
class CameraPanel : public QWidget {
    Q_OBJECT
  public:
    explicit CameraPanel(SceneDocument* doc, QWidget* parent = nullptr);

  private:
    void refresh();

    SceneDocument* doc_;
    std::vector<DoubleField*> fields_;
};

class RenderRecord;

// Render settings (image size, depth, samples, precision) and the scene's
// background and ambient colours; given a record, the presets and the
// predicted time and error above them (preset_controls.h).
class RenderSettingsPanel : public QWidget {
    Q_OBJECT
  public:
    // With a record and a quality choice: the presets, the quality target and
    // the predictions (preset_controls.h) above the settings.
    explicit RenderSettingsPanel(SceneDocument* doc, RenderRecord* record = nullptr,
                                 QualityChoice* quality = nullptr, QWidget* parent = nullptr);

  private:
    void addIntRows(QFormLayout* form);
    void addPrecisionRow(QFormLayout* form);
    ColorButton* addColourRow(QFormLayout* form, const SceneField& field, const QString& name,
                              Vec3 Scene::*member);
    // Depth and samples rest while a target or Whitted 1980 sampling chooses them.
    void followTarget(const QualityChoice* quality);
    void refresh();

    SceneDocument* doc_;
    std::vector<IntField*> fields_;
    QComboBox* precision_;
    ColorButton* background_;
    ColorButton* ambient_;
};

}  // namespace whitted::ui
