// A Qt list model over one list of the scene (spheres, lights or materials):
// one row per item, the item's name as its text, renamed in place through the document.
#pragma once

#include <QAbstractListModel>

#include "document/scene_document.h"

namespace whitted::ui {

// Reads the document's scene on every call and keeps no copy of the list, so a
// scene of 100,000 spheres costs nothing until rows are painted.
class SceneListModel : public QAbstractListModel {
    Q_OBJECT
  public:
    SceneListModel(SceneDocument* doc, ItemKind kind, QObject* parent = nullptr);

    ItemKind kind() const { return kind_; }

    int rowCount(const QModelIndex& parent = QModelIndex()) const override;
    QVariant data(const QModelIndex& index, int role = Qt::DisplayRole) const override;
    Qt::ItemFlags flags(const QModelIndex& index) const override;
    // Renames the item as one undo step (a material's spheres follow it). An empty
    // or duplicate name is refused: returns false, emits editRefused, and the old
    // name stays.
    bool setData(const QModelIndex& index, const QVariant& value, int role = Qt::EditRole) override;

  signals:
    void editRefused(const QString& reason);

  private:
    void onStructureChanged();

    SceneDocument* doc_;
    ItemKind kind_;
    // The row count the views were last told about. The document changes its
    // scene before announcing it, so rowCount() must not read the new size early.
    int rows_ = 0;
};

}  // namespace whitted::ui
