#include "editor/help_dialogs.h"

#include <algorithm>

#include <QAbstractButton>
#include <QAbstractSlider>
#include <QAbstractSpinBox>
#include <QAction>
#include <QApplication>
#include <QComboBox>
#include <QDialog>
#include <QDialogButtonBox>
#include <QFormLayout>
#include <QHeaderView>
#include <QLabel>
#include <QLineEdit>
#include <QMenu>
#include <QMenuBar>
#include <QMessageBox>
#include <QScreen>
#include <QScrollBar>
#include <QTableWidget>
#include <QVBoxLayout>

#include "image/image_io.h"
#include "tracer/kernel_dispatch.h"

#ifndef WHITTED_VERSION
#define WHITTED_VERSION "unknown"
#endif

namespace whitted::ui {

namespace {

QString plainText(const QAction* a) {
    QString text = a->text();
    text.remove(QLatin1Char('&'));
    if (text.endsWith(QStringLiteral("…"))) text.chop(1);
    return text;
}

QString keysText(const QAction* a) {
    QStringList keys;
    for (const QKeySequence& k : a->shortcuts()) keys << k.toString(QKeySequence::NativeText);
    return keys.join(QStringLiteral(", "));
}

// The menu title an action sits in ("Edit", "View > Camera"), or "".
QString menuPath(const QAction* a) {
    for (QObject* w : a->associatedObjects()) {
        auto* menu = qobject_cast<QMenu*>(w);
        if (!menu) continue;
        QStringList titles;
        for (QMenu* m = menu; m;
             m = qobject_cast<QMenu*>(m->menuAction()->associatedObjects().value(0)))
            titles.prepend(m->title().remove(QLatin1Char('&')));
        return titles.join(QStringLiteral(" > "));
    }
    return {};
}

}  // namespace

QList<ControlRow> controlRows(QWidget* window, const QList<QPair<QString, QString>>& mouse) {
    QList<ControlRow> rows;
    QList<const QAction*> seen;
    // Menus first, in their order, then actions that live only on a widget.
    QList<QAction*> actions;
    for (QMenu* menu : window->findChildren<QMenu*>()) actions += menu->actions();
    actions += window->findChildren<QAction*>();
    for (const QAction* a : actions) {
        if (a->shortcuts().isEmpty() || seen.contains(a)) continue;
        seen << a;
        QString group = menuPath(a);
        if (group.isEmpty()) group = QObject::tr("Other");
        rows.push_back({group, keysText(a), plainText(a)});
    }
    for (const auto& [gesture, effect] : mouse)
        rows.push_back({QObject::tr("Mouse in the view"), gesture, effect, true});
    return rows;
}

namespace {

// Wide enough for every row's text (the mouse's rows are long), so that none
// of it hides behind a horizontal scroll bar, as far as the screen allows;
// at least 620 pixels.
int keyboardHelpWidth(const QWidget* window, const QTableWidget* table, const QLayout* layout,
                      int columnsWidth) {
    const QMargins margins = layout->contentsMargins();
    int width = columnsWidth + table->verticalScrollBar()->sizeHint().width() +
                2 * table->frameWidth() + margins.left() + margins.right();
    if (const QScreen* screen = window ? window->screen() : nullptr)
        width = std::min(width, screen->availableGeometry().width() * 9 / 10);
    return std::max(620, width);
}

}  // namespace

QDialog* showKeyboardHelp(QWidget* window, const QList<ControlRow>& rows) {
    auto* dialog = new QDialog(window);
    dialog->setObjectName(QStringLiteral("keyboardHelp"));
    dialog->setWindowTitle(QObject::tr("Keyboard and Mouse"));
    dialog->setAttribute(Qt::WA_DeleteOnClose);
    auto* table = new QTableWidget(int(rows.size()), 3, dialog);
    table->setObjectName(QStringLiteral("controlsTable"));
    table->setHorizontalHeaderLabels(
        {QObject::tr("Where"), QObject::tr("Keys or gesture"), QObject::tr("What it does")});
    table->verticalHeader()->hide();
    table->setEditTriggers(QAbstractItemView::NoEditTriggers);
    for (int r = 0; r < rows.size(); ++r) {
        table->setItem(r, 0, new QTableWidgetItem(rows[r].group));
        table->setItem(r, 1, new QTableWidgetItem(rows[r].keys));
        table->setItem(r, 2, new QTableWidgetItem(rows[r].action));
    }
    table->resizeColumnsToContents();
    const int columnsWidth = table->horizontalHeader()->length();
    table->horizontalHeader()->setStretchLastSection(true);
    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Close, dialog);
    QObject::connect(buttons, &QDialogButtonBox::rejected, dialog, &QDialog::close);
    auto* layout = new QVBoxLayout(dialog);
    layout->addWidget(table);
    layout->addWidget(buttons);
    dialog->resize(keyboardHelpWidth(window, table, layout, columnsWidth), 560);
    dialog->open();
    return dialog;
}

QDialog* showAbout(QWidget* window) {
    auto* box = new QMessageBox(window);
    box->setObjectName(QStringLiteral("aboutBox"));
    box->setAttribute(Qt::WA_DeleteOnClose);
    box->setWindowTitle(QObject::tr("About Whitted"));
    box->setIconPixmap(QApplication::windowIcon().pixmap(64, 64));
    box->setText(QObject::tr("<b>Whitted %1</b>").arg(QStringLiteral(WHITTED_VERSION)));
    box->setInformativeText(
        QObject::tr("A scene editor for a classic Whitted ray tracer: spheres, lights and "
                    "materials, shadows, reflection and refraction, in float or double.\n\n"
                    "Qt %1 (built with %2)\nOpenImageIO %3\nTracing kernel: %4")
            .arg(QString::fromLatin1(qVersion()), QStringLiteral(QT_VERSION_STR),
                 QString::fromStdString(openImageIOVersion()),
                 QString::fromStdString(activeKernelDescription())));
    box->open();
    return box;
}

void addShortcutsToToolTips(QWidget* root) {
    for (QAction* a : root->findChildren<QAction*>()) {
        // Marked, so that a second call does not add the keys twice.
        if (a->shortcuts().isEmpty() || a->property("keysInToolTip").toBool()) continue;
        a->setToolTip(QStringLiteral("%1 (%2)").arg(a->toolTip(), keysText(a)));
        a->setProperty("keysInToolTip", true);
    }
}

namespace {

QList<QWidget*> inputsOf(QWidget* field) {
    QList<QWidget*> inputs;
    auto isInput = [](QWidget* w) {
        return qobject_cast<QAbstractSpinBox*>(w) || qobject_cast<QComboBox*>(w) ||
               qobject_cast<QLineEdit*>(w) || qobject_cast<QAbstractSlider*>(w) ||
               qobject_cast<QAbstractButton*>(w);
    };
    if (isInput(field)) inputs << field;
    for (QWidget* w : field->findChildren<QWidget*>())
        if (isInput(w) && !qobject_cast<QAbstractSpinBox*>(w->parentWidget()) &&
            !qobject_cast<QComboBox*>(w->parentWidget()))
            inputs << w;
    return inputs;
}

}  // namespace

void addFieldToolTips(QWidget* root) {
    for (QFormLayout* form : root->findChildren<QFormLayout*>()) {
        for (int row = 0; row < form->rowCount(); ++row) {
            auto* label = form->itemAt(row, QFormLayout::LabelRole);
            auto* field = form->itemAt(row, QFormLayout::FieldRole);
            auto* labelWidget = label ? qobject_cast<QLabel*>(label->widget()) : nullptr;
            if (!labelWidget || !field || !field->widget()) continue;
            QString name = labelWidget->text().remove(QLatin1Char('&'));
            if (name.endsWith(QLatin1Char(':'))) name.chop(1);
            for (QWidget* input : inputsOf(field->widget())) {
                const QString own = input->toolTip();
                // One-letter tips name a vector's part: keep them, after the row.
                if (own.size() > 1) continue;
                input->setToolTip(own.isEmpty() ? name : QStringLiteral("%1: %2").arg(name, own));
            }
        }
    }
}

}  // namespace whitted::ui
