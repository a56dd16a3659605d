// SceneListModel: the rows, in-place renaming, and following the document.
#include "panels/scene_list_model.h"

namespace whitted::ui {

SceneListModel::SceneListModel(SceneDocument* doc, ItemKind kind, QObject* parent)
    : QAbstractListModel(parent), doc_(doc), kind_(kind), rows_(itemCount(doc->scene(), kind)) {
    connect(doc_, &SceneDocument::structureChanged, this, &SceneListModel::onStructureChanged);
    // Nothing on sceneChanged: names change with the structure, and the one
    // other thing a row shows, a sphere's tooltip (its material), the view
    // reads when it shows the tooltip. Even one row's dataChanged() made the
    // list view lay out all its rows again, 5 ms for 100,000, on every edit.
}

int SceneListModel::rowCount(const QModelIndex& parent) const {
    return parent.isValid() ? 0 : rows_;
}

QVariant SceneListModel::data(const QModelIndex& index, int role) const {
    const int row = index.row();
    if (!index.isValid() || row >= itemCount(doc_->scene(), kind_)) return {};
    switch (role) {
        case Qt::DisplayRole:
        case Qt::EditRole:
            return itemName(doc_->scene(), kind_, row);
        case Qt::ToolTipRole:
            if (kind_ == ItemKind::Sphere)
                return tr("%1 (material %2)")
                    .arg(itemName(doc_->scene(), kind_, row),
                         QString::fromStdString(doc_->scene().spheres[row].material));
            return itemName(doc_->scene(), kind_, row);
        default:
            return {};
    }
}

Qt::ItemFlags SceneListModel::flags(const QModelIndex& index) const {
    if (!index.isValid()) return Qt::NoItemFlags;
    return Qt::ItemIsEnabled | Qt::ItemIsSelectable | Qt::ItemIsEditable | Qt::ItemNeverHasChildren;
}

bool SceneListModel::setData(const QModelIndex& index, const QVariant& value, int role) {
    const int row = index.row();
    if (!index.isValid() || role != Qt::EditRole || row >= itemCount(doc_->scene(), kind_))
        return false;
    const QString oldName = itemName(doc_->scene(), kind_, row);
    const QString newName = value.toString().trimmed();
    if (newName == oldName) return true;
    const QString noun = kindNoun(kind_);
    // An empty or taken name is refused by the document, in the user's words
    // (edit_messages.h): "There is already a sphere named “ball”".
    const std::string oldStd = oldName.toStdString(), newStd = newName.toStdString();
    QString error;
    const bool ok = doc_->edit(
        tr("Rename %1 %2 to %3").arg(noun, oldName, newName),
        [&](Scene& scene) {
            switch (kind_) {
                case ItemKind::Sphere:
                    scene.spheres[row].name = newStd;
                    break;
                case ItemKind::Light:
                    scene.lights[row].name = newStd;
                    break;
                case ItemKind::Material:
                    scene.materials[row].name = newStd;
                    for (Sphere& sphere : scene.spheres)
                        if (sphere.material == oldStd) sphere.material = newStd;
                    break;
            }
        },
        &error);
    if (!ok) emit editRefused(error);
    return ok;
}

void SceneListModel::onStructureChanged() {
    const int rows = itemCount(doc_->scene(), kind_);
    if (rows == rows_) {
        // Renamed in place (or replaced by a list of the same length): a reset
        // would drop the selection and scroll position for nothing.
        if (rows > 0) emit dataChanged(index(0), index(rows - 1));
        return;
    }
    beginResetModel();
    rows_ = rows;
    endResetModel();
}

}  // namespace whitted::ui
