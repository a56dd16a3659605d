#include "ray_tree_dock/ray_tree_view.h"

#include <algorithm>
#include <cmath>

#include <QFont>
#include <QHeaderView>
#include <QIcon>
#include <QLabel>
#include <QPainter>
#include <QPixmap>
#include <QSignalBlocker>
#include <QTreeWidget>
#include <QTreeWidgetItemIterator>
#include <QVBoxLayout>

#include "document/scene_document.h"
#include "image/image_compare.h"
#include "viewport/image_convert.h"

namespace whitted::ui {

namespace {

// What a ray adds right after it, what the reader came for, and the same in
// the other precision beside it.
enum Column { RayColumn, AddsColumn, OtherColumn, HitColumn, WeightColumn, DistanceColumn };

// Figures as the dock lists them: linear colours to four decimals.
QString rgbText(const Vec3& c) {
    return QStringLiteral("%1, %2, %3").arg(c.r, 0, 'f', 4).arg(c.g, 0, 'f', 4).arg(c.b, 0, 'f', 4);
}

// A step of the 8-bit picture or more, as the Precision Check counts them.
bool differ(const Vec3& a, const Vec3& b) {
    const float fa[3] = {float(a.r), float(a.g), float(a.b)};
    const float fb[3] = {float(b.r), float(b.g), float(b.b)};
    return displayDifference(fa, fb) >= 1.0f / 255.0f;
}

QIcon swatch(const QColor& colour) {
    QPixmap pixmap(12, 12);
    pixmap.fill(Qt::transparent);
    QPainter painter(&pixmap);
    painter.setPen(QColor(0, 0, 0, 160));
    painter.setBrush(colour);
    painter.drawRect(0, 0, 11, 11);
    return QIcon(pixmap);
}

QString kindText(const RayTreeNode& node, const QStringList& lights) {
    switch (node.kind) {
        case RayTreeNode::Kind::Camera:
            return RayTreeView::tr("Camera");
        case RayTreeNode::Kind::Reflection:
            return RayTreeView::tr("Reflection");
        case RayTreeNode::Kind::Refraction:
            return RayTreeView::tr("Refraction");
        case RayTreeNode::Kind::Shadow:
            return RayTreeView::tr("Shadow to %1").arg(lights.value(node.light));
    }
    return {};
}

QString hitText(const RayTreeNode& node, const QHash<int, QString>& spheres) {
    if (node.kind == RayTreeNode::Kind::Shadow) {
        if (node.transmittance >= 1) return RayTreeView::tr("the light, unblocked");
        if (node.transmittance <= 0) return RayTreeView::tr("blocked: in shadow");
        return RayTreeView::tr("the light, %1 % through glass")
            .arg(node.transmittance * 100, 0, 'f', 1);
    }
    if (node.hit < 0) return RayTreeView::tr("nothing: the sky");
    QString text = spheres.value(node.hit) +
                   (node.entering ? RayTreeView::tr(", entering") : RayTreeView::tr(", leaving"));
    if (node.totalInternalReflection) text += RayTreeView::tr("; total internal reflection");
    return text;
}

// The node of `other` at the place `node` has in its own tree: the same
// child index at every level, or none when the other tree has no such ray.
const RayTreeNode* childOf(const RayTreeNode* other, std::size_t index) {
    if (!other || index >= other->children.size()) return nullptr;
    return &other->children[index];
}

}  // namespace

RayTreeView::RayTreeView(SceneDocument* doc, QWidget* parent)
    : QWidget(parent), doc_(doc), summary_(new QLabel), rows_(new QTreeWidget) {
    summary_->setObjectName(QStringLiteral("rayTreeSummary"));
    summary_->setWordWrap(true);
    summary_->setTextInteractionFlags(Qt::TextSelectableByMouse);
    summary_->setText(
        tr("Ctrl+click a pixel of the picture to see the rays that make its colour."));
    rows_->setObjectName(QStringLiteral("rayTreeRows"));
    rows_->setHeaderLabels({tr("Ray"), tr("Adds (linear r, g, b)"), tr("In the other precision"),
                            tr("Hits"), tr("Weight"), tr("Distance")});
    rows_->setAlternatingRowColors(true);
    rows_->setUniformRowHeights(true);
    rows_->header()->setSectionResizeMode(QHeaderView::ResizeToContents);
    auto* layout = new QVBoxLayout(this);
    layout->addWidget(summary_);
    layout->addWidget(rows_, 1);

    connect(&worker_, &RayTreeWorker::treeReady, this, [this] {
        if (std::optional<RayTreeResult> tree = worker_.takeTree()) onTree(*tree);
    });
    connect(doc_, &SceneDocument::sceneChanged, this, [this] {
        if (isVisible()) trace();
    });
    connect(rows_, &QTreeWidget::currentItemChanged, this, [this](QTreeWidgetItem* item) {
        highlighted_ = item ? item->data(RayColumn, Qt::UserRole).toInt() : -1;
        emit overlayChanged();
    });
}

void RayTreeView::inspect(QPoint pixel) {
    const Scene& scene = doc_->scene();
    place_ =
        QPointF((pixel.x() + 0.5) / scene.render.width, (pixel.y() + 0.5) / scene.render.height);
    trace();
}

std::optional<QPoint> RayTreeView::pixel() const {
    if (!place_) return std::nullopt;
    const Scene& scene = doc_->scene();
    return QPoint(
        std::clamp(int(std::floor(place_->x() * scene.render.width)), 0, scene.render.width - 1),
        std::clamp(int(std::floor(place_->y() * scene.render.height)), 0, scene.render.height - 1));
}

void RayTreeView::trace() {
    if (const auto at = pixel()) worker_.request(doc_->snapshot(), *at);
}

void RayTreeView::showEvent(QShowEvent* e) {
    QWidget::showEvent(e);
    trace();  // edits made while hidden were not followed
    emit overlayChanged();
}

void RayTreeView::hideEvent(QHideEvent* e) {
    QWidget::hideEvent(e);
    // A closed dock draws nothing over the picture.
    emit overlayChanged();
}

void RayTreeView::onTree(const RayTreeResult& result) {
    if (result.generation != worker_.latestGeneration()) return;  // an older scene's
    shown_ = result;
    rays_ = result.error.isEmpty() ? drawnRays(own().root) : std::vector<DrawnRay>{};
    highlighted_ = std::min(highlighted_, int(rays_.size()) - 1);
    fillRows();
    emit treeShown(result.generation);
    emit overlayChanged();
}

const PixelRayTree& RayTreeView::own() const {
    return shown_.precision == Precision::Float ? shown_.inFloat : shown_.inDouble;
}

const PixelRayTree& RayTreeView::other() const {
    return shown_.precision == Precision::Float ? shown_.inDouble : shown_.inFloat;
}

void RayTreeView::fillRows() {
    const int keep = highlighted_;
    const QSignalBlocker quiet(rows_);
    rows_->clear();
    summary_->setText(summary());
    if (!shown_.error.isEmpty()) return;
    rows_->headerItem()->setText(
        OtherColumn, shown_.precision == Precision::Float ? tr("In double") : tr("In float"));
    int rayIndex = 0;
    addRow(nullptr, own().root, &other().root, rayIndex);
    rows_->expandAll();
    // The same ray stays selected as the tree follows an edit.
    for (QTreeWidgetItemIterator it(rows_); *it; ++it)
        if ((*it)->data(RayColumn, Qt::UserRole).toInt() == keep && keep >= 0)
            rows_->setCurrentItem(*it);
}

QTreeWidgetItem* RayTreeView::addRow(QTreeWidgetItem* parent, const RayTreeNode& node,
                                     const RayTreeNode* other, int& rayIndex) {
    auto* item = parent ? new QTreeWidgetItem(parent) : new QTreeWidgetItem(rows_);
    item->setData(RayColumn, Qt::UserRole, rayIndex++);
    item->setText(RayColumn, kindText(node, shown_.lightNames));
    item->setIcon(RayColumn, swatch(rayColour(node.kind)));
    item->setText(HitColumn, hitText(node, shown_.sphereNames));
    item->setText(DistanceColumn, QString::number(node.t, 'g', 5));
    item->setText(WeightColumn, QString::number(node.weight, 'g', 4));
    const bool shadow = node.kind == RayTreeNode::Kind::Shadow;
    item->setText(AddsColumn, shadow ? tr("(in its hit's)") : rgbText(node.contribution));
    if (!shadow) item->setIcon(AddsColumn, swatch(displayColour(node.contribution)));
    // The same ray in the other precision hits the same thing (a shadow ray:
    // lets through the same light, to an 8-bit step).
    const bool sameHit = other && other->hit == node.hit &&
                         other->totalInternalReflection == node.totalInternalReflection &&
                         std::abs(other->transmittance - node.transmittance) < 1.0 / 255;
    if (!other)
        item->setText(OtherColumn, tr("no such ray"));
    else if (!sameHit)
        item->setText(OtherColumn, hitText(*other, shown_.sphereNames));
    else
        item->setText(OtherColumn, shadow ? tr("the same") : rgbText(other->contribution));
    if (!sameHit || (!shadow && differ(other->contribution, node.contribution))) {
        item->setForeground(OtherColumn, QColor(220, 60, 40));
        item->setToolTip(OtherColumn, tr("Float and double differ here by an 8-bit step or more"));
    }
    if (node.cutOff) {
        auto* cut = new QTreeWidgetItem(item);
        cut->setData(RayColumn, Qt::UserRole, -1);
        cut->setText(RayColumn, tr("Cut off at depth %1").arg(node.depth));
        cut->setText(HitColumn, tr("the maximum depth: its rays are not traced"));
        cut->setText(AddsColumn, tr("would add %1").arg(rgbText(node.pastDepth)));
        QFont italic = cut->font(RayColumn);
        italic.setItalic(true);
        for (int c = RayColumn; c <= DistanceColumn; ++c) cut->setFont(c, italic);
    }
    for (std::size_t i = 0; i < node.children.size(); ++i)
        addRow(item, node.children[i], childOf(other, i), rayIndex);
    return item;
}

QString RayTreeView::summary() const {
    if (!shown_.error.isEmpty()) return tr("This pixel cannot be traced: %1").arg(shown_.error);
    const bool isFloat = shown_.precision == Precision::Float;
    const Vec3 value = own().value, otherValue = other().value;
    const QString agreement = differ(value, otherValue)
                                  ? tr("<b>In %1: %2</b>, an 8-bit step or more apart.")
                                  : tr("In %1: %2, the same on screen.");
    return tr("Pixel %1, %2 of %3 × %4, traced through its centre at depth %5: <b>%6</b> in "
              "%7, the rendered value (linear r, g, b). ")
               .arg(shown_.pixel.x())
               .arg(shown_.pixel.y())
               .arg(shown_.width)
               .arg(shown_.height)
               .arg(shown_.maxDepth)
               .arg(rgbText(value))
               .arg(isFloat ? tr("float") : tr("double")) +
           agreement.arg(isFloat ? tr("double") : tr("float")).arg(rgbText(otherValue)) +
           tr(" Ctrl+click another pixel to inspect it.");
}

}  // namespace whitted::ui
