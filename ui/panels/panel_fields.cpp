#include "panels/panel_fields.h"

#include <QFont>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>

namespace whitted::ui {

QWidget* makeVectorRow(const QString& name,
                       const std::function<DoubleField*(int axis, const QString& name)>& make,
                       std::vector<DoubleField*>& fields) {
    auto* row = new QWidget;
    auto* layout = new QHBoxLayout(row);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->setSpacing(4);
    static const char* const kAxes[] = {"X", "Y", "Z"};
    for (int axis = 0; axis < 3; ++axis) {
        DoubleField* field = make(axis, name + QLatin1String(kAxes[axis]));
        field->spinBox()->setToolTip(QString(QLatin1Char('x' + axis)));
        fields.push_back(field);
        layout->addWidget(field);
    }
    return row;
}

QFormLayout* makeForm(QWidget* page) {
    auto* form = new QFormLayout(page);
    form->setFieldGrowthPolicy(QFormLayout::AllNonFixedFieldsGrow);
    form->setLabelAlignment(Qt::AlignRight | Qt::AlignVCenter);
    form->setRowWrapPolicy(QFormLayout::DontWrapRows);
    return form;
}

QLabel* makeNameLabel(const QString& objectName) {
    auto* label = new QLabel;
    label->setObjectName(objectName);
    label->setTextInteractionFlags(Qt::TextSelectableByMouse);
    QFont font = label->font();
    font.setBold(true);
    label->setFont(font);
    return label;
}

void refreshAll(const std::vector<DoubleField*>& fields) {
    for (DoubleField* field : fields) field->refresh();
}

std::vector<int> editTargets(const SceneDocument& doc, ItemKind kind, int shown) {
    const SceneSelection& selection = *doc.selection();
    std::vector<int> targets{shown};
    if (!selection.contains(kind, shown)) return targets;
    for (int i : selection.indices())
        if (i != shown) targets.push_back(i);
    return targets;
}

}  // namespace whitted::ui
