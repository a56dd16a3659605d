// The sphere page of the property panel: centre, radius, and the sphere's
// material in place (which one, how many spheres share it, its main finish,
// and "Make unique" to give this sphere a copy of its own).
#pragma once

#include <memory>
#include <string>
#include <vector>

#include <QWidget>

#include "document/scene_document.h"

class QComboBox;
class QLabel;
class QPushButton;

namespace whitted::ui {

class DoubleField;
class MaterialRows;

class SpherePage : public QWidget {
    Q_OBJECT
  public:
    explicit SpherePage(SceneDocument* doc, QWidget* parent = nullptr);
    ~SpherePage() override;

    void setIndex(int index);  // the sphere shown; refreshes
    void refresh();            // re-reads the scene; emits nothing

  private:
    QWidget* buildMaterialChoice();
    void refreshMaterialChoice(const Sphere& sphere);
    // The shown sphere, then the others selected with it: what an edit changes.
    std::vector<int> targets() const;
    // The materials of those spheres, each once, the shown sphere's first: what
    // the material rows change.
    std::vector<int> materialTargets(const Scene& scene) const;
    // "ball", or "ball and 3 other spheres" for an undo step's name.
    QString sphereName() const;
    QString materialName() const;

    SceneDocument* doc_;
    int index_ = -1;
    QLabel* name_;
    QComboBox* material_ = nullptr;
    QLabel* users_ = nullptr;
    QPushButton* makeUnique_ = nullptr;
    std::vector<DoubleField*> fields_;
    std::unique_ptr<MaterialRows> materialRows_;
    std::vector<int> materials_;  // materialTargets() at the last refresh
    // The count of the spheres sharing the shown material, and what it was
    // counted for: the material and how many spheres there were.
    int usersCount_ = 0;
    std::string countedMaterial_;
    std::size_t countedAmong_ = 0;
};

}  // namespace whitted::ui
