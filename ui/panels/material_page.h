// The material page of the property panel: a preset chooser, the finish, and
// the checker pattern of the selected material.
#pragma once

#include <functional>
#include <memory>
#include <vector>

#include <QWidget>

#include "document/scene_document.h"

class QCheckBox;
class QComboBox;
class QFormLayout;
class QLabel;

namespace whitted::ui {

class ColorButton;
class DoubleField;
class MaterialRows;

class MaterialPage : public QWidget {
    Q_OBJECT
  public:
    explicit MaterialPage(SceneDocument* doc, QWidget* parent = nullptr);
    ~MaterialPage() override;

    void setIndex(int index);  // the material shown; refreshes
    void refresh();            // re-reads the scene; emits nothing

  private:
    QComboBox* buildPresetChooser();
    void addCheckerRows(QFormLayout* form);
    // The shown material, then the others selected with it: what an edit changes.
    std::vector<int> targets() const;
    // "glass", or "glass (and 2 more)" for an undo step's name.
    QString materialName() const;
    std::function<QString()> changeText(const QString& what) const;
    void editMaterial(const QString& what, const std::function<void(Material&)>& change);

    SceneDocument* doc_;
    int index_ = -1;
    QLabel* name_;
    QComboBox* preset_ = nullptr;
    std::unique_ptr<MaterialRows> rows_;
    QCheckBox* checker_ = nullptr;
    ColorButton* checkerColor_ = nullptr;
    DoubleField* checkerSize_ = nullptr;
};

}  // namespace whitted::ui
