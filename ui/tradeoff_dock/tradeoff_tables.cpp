#include "tradeoff_dock/tradeoff_tables.h"

#include <QHeaderView>
#include <QStyle>
#include <QTableWidget>

#include <cmath>

#include "document/settings_words.h"
#include "tradeoff_dock/tradeoff_points.h"

namespace whitted::ui {

namespace {

// Shows formatted text, sorts by the number behind it.
class NumberItem : public QTableWidgetItem {
  public:
    NumberItem(const QString& text, double value) : QTableWidgetItem(text), value_(value) {
        setTextAlignment(Qt::AlignRight | Qt::AlignVCenter);
    }
    bool operator<(const QTableWidgetItem& other) const override {
        if (const auto* n = dynamic_cast<const NumberItem*>(&other)) return value_ < n->value_;
        return QTableWidgetItem::operator<(other);
    }

  private:
    double value_;
};

QTableWidgetItem* number(double value, int decimals) {
    return new NumberItem(QString::number(value, 'f', decimals), value);
}

QTableWidgetItem* text(const QString& s) {
    return new QTableWidgetItem(s);
}

QTableWidgetItem* psnr(double db) {
    // Identical images: +infinity, shown as such and sorted last.
    return new NumberItem(std::isfinite(db) ? QString::number(db, 'f', 1) : QStringLiteral("∞"),
                          db);
}

QTableWidget* makeTable(const QString& name, const QStringList& headers) {
    auto* table = new QTableWidget(0, int(headers.size()));
    table->setObjectName(name);
    table->setHorizontalHeaderLabels(headers);
    table->setEditTriggers(QAbstractItemView::NoEditTriggers);
    table->setSelectionBehavior(QAbstractItemView::SelectRows);
    table->verticalHeader()->hide();
    table->verticalHeader()->setDefaultSectionSize(table->fontMetrics().height() + 6);
    // Every column as wide as its title and cells; not stretched, so that the
    // header's length is the width the table needs (tableContentWidth).
    table->horizontalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
    table->horizontalHeader()->setStretchLastSection(false);
    // Unsorted (in the order given) until the user clicks a header.
    table->horizontalHeader()->setSortIndicator(-1, Qt::AscendingOrder);
    table->setSortingEnabled(true);
    return table;
}

void setRow(QTableWidget* table, int row, const std::vector<QTableWidgetItem*>& items,
            const QString& tooltip) {
    for (int c = 0; c < int(items.size()); ++c) {
        items[c]->setToolTip(tooltip);
        table->setItem(row, c, items[c]);
    }
}

}  // namespace

int tableContentWidth(const QTableWidget* table) {
    // Room for a vertical scroll bar too: rows arriving must not cover a column.
    const int scrollBar = table->style()->pixelMetric(QStyle::PM_ScrollBarExtent, nullptr, table);
    return table->horizontalHeader()->length() + 2 * table->frameWidth() + scrollBar;
}

// The columns a user compares by come first: the dock is often narrow. Units
// on a second line keep the columns of small numbers narrow.
QTableWidget* makePinnedTable() {
    return makeTable(
        QStringLiteral("pinnedTable"),
        {QObject::tr("#"), QObject::tr("Samples"), QObject::tr("Depth"), QObject::tr("Precision"),
         QObject::tr("Time\n(s)"), QObject::tr("RMSE\n8-bit"), QObject::tr("PSNR\n(dB)"),
         QObject::tr("Largest"), QObject::tr("Size"), QObject::tr("Note")});
}

QTableWidget* makeMeasureTable() {
    return makeTable(QStringLiteral("measureTable"),
                     {QObject::tr("Samples"), QObject::tr("Depth"), QObject::tr("Precision"),
                      QObject::tr("Scale"), QObject::tr("Time\n(s)"), QObject::tr("RMSE\n8-bit"),
                      QObject::tr("PSNR\n(dB)"), QObject::tr("Front"), QObject::tr("Runs"),
                      QObject::tr("Mrays/s"), QObject::tr("Size")});
}

void fillPinnedTable(QTableWidget* table, const std::vector<PinnedPoint>& points) {
    table->setSortingEnabled(false);
    table->setRowCount(int(points.size()));
    for (int row = 0; row < int(points.size()); ++row) {
        const PinnedPoint& p = points[points.size() - 1 - std::size_t(row)];
        const RenderSettings& s = p.settings;
        std::vector<QTableWidgetItem*> items{
            number(double(p.id), 0), number(s.samplesPerPixel, 0), number(s.maxDepth, 0),
            text(precisionText(s.precision)), number(p.seconds, 3)};
        if (p.error) {
            items.push_back(number(p.error->rmseSrgb8, 3));
            items.push_back(psnr(p.error->psnrSrgb8));
            items.push_back(number(p.error->largest, 1));
        } else {
            for (int i = 0; i < 3; ++i) items.push_back(text(QString()));
        }
        items.push_back(text(QStringLiteral("%1 × %2").arg(s.width).arg(s.height)));
        items.push_back(text(p.error            ? QString()
                             : p.note.isEmpty() ? QObject::tr("measuring…")
                                                : p.note));
        setRow(table, row, items, pointTooltip(p));
    }
    table->setSortingEnabled(true);
}

void fillMeasureTable(QTableWidget* table, const std::vector<TradeoffPoint>& points) {
    table->setSortingEnabled(false);
    table->setRowCount(int(points.size()));
    for (int row = 0; row < int(points.size()); ++row) {
        const TradeoffPoint& p = points[std::size_t(row)];
        const TradeoffSettings& s = p.settings;
        setRow(
            table, row,
            {number(s.samplesPerPixel, 0), number(s.maxDepth, 0), text(precisionText(s.precision)),
             number(s.resolutionScale, 2), number(p.seconds, 4), number(p.error.rmseSrgb8, 3),
             psnr(p.error.psnrSrgb8), text(p.pareto ? QObject::tr("yes") : QString()),
             number(p.runs, 0), number(p.mraysPerSecond, 1),
             text(QStringLiteral("%1 × %2").arg(p.width).arg(p.height))},
            pointTooltip(p));
    }
    table->setSortingEnabled(true);
}

}  // namespace whitted::ui
