#include "document/autosave.h"

#include <QCoreApplication>
#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QJsonDocument>
#include <QJsonObject>
#include <QStandardPaths>
#include <QUuid>

#include <algorithm>

#include "base/atomic_file.h"
#include "document/scene_document.h"
#include "scene/scene_io.h"

namespace whitted::ui {

namespace {

QString metaPath(const QString& slot) {
    return slot + QStringLiteral(".meta");
}
QString scenePath(const QString& slot) {
    return slot + QStringLiteral(".json");
}
QString lockPath(const QString& slot) {
    return slot + QStringLiteral(".lock");
}

}  // namespace

QString Autosave::defaultDirectory() {
    // WHITTED_RECOVERY_DIR: for tests, and for anyone who wants the copies elsewhere.
    const QString fromEnvironment = qEnvironmentVariable("WHITTED_RECOVERY_DIR");
    if (!fromEnvironment.isEmpty()) return fromEnvironment;
    return QStandardPaths::writableLocation(QStandardPaths::AppLocalDataLocation) +
           QStringLiteral("/recovery");
}

Autosave::Autosave(SceneDocument* doc, QString directory, QObject* parent)
    : QObject(parent), doc_(doc), dir_(directory.isEmpty() ? defaultDirectory() : directory) {
    QDir().mkpath(dir_);
    slot_ = dir_ + QLatin1Char('/') + QUuid::createUuid().toString(QUuid::WithoutBraces);
    lock_ = std::make_unique<QLockFile>(lockPath(slot_));
    lock_->setStaleLockTime(0);  // only a dead owner makes a lock stale, never age
    lock_->tryLock(0);
    timer_.setSingleShot(true);
    timer_.setInterval(2000);
    connect(&timer_, &QTimer::timeout, this, &Autosave::writeNow);
    connect(doc_, &SceneDocument::sceneChanged, this, &Autosave::onSceneChanged);
    connect(doc_, &SceneDocument::modifiedChanged, this, [this](bool modified) {
        if (!modified) clear();  // saved, or undone back to the file
    });
}

Autosave::~Autosave() {
    clear();
    lock_.reset();  // unlocks and removes the lock file
}

void Autosave::onSceneChanged() {
    // Restarted by every change: one copy per burst of edits. Whether there is
    // anything to copy is decided when it fires: during an edit the undo stack
    // does not yet say the scene is modified.
    timer_.start();
}

void Autosave::writeNow() {
    if (!doc_->isModified()) {
        clear();
        return;
    }
    QString error;
    try {
        saveScene(doc_->scene(), scenePath(slot_).toStdString());
        QJsonObject meta;
        meta[QStringLiteral("original")] = doc_->filePath();
        meta[QStringLiteral("written")] = QDateTime::currentDateTimeUtc().toString(Qt::ISODate);
        const QByteArray text = QJsonDocument(meta).toJson();
        replaceFileAtomically(metaPath(slot_).toStdString(), [&](const std::filesystem::path& p) {
            writeAllBytes(p, {text.constData(), std::size_t(text.size())});
        });
    } catch (const std::exception& e) {
        // Autosave must never get in the user's way: the failure is reported
        // (status bar) and the next burst of edits tries again.
        error = QString::fromStdString(e.what());
    }
    emit written(error);
}

void Autosave::clear() {
    timer_.stop();
    QFile::remove(scenePath(slot_));
    QFile::remove(metaPath(slot_));
}

std::vector<Recovery> Autosave::orphans(const QString& directory) {
    std::vector<Recovery> found;
    const QDir dir(directory);
    for (const QString& name : dir.entryList({QStringLiteral("*.json")}, QDir::Files)) {
        const QString slot = dir.filePath(name.chopped(5));
        // Held by a running editor (this one included): not an orphan.
        QLockFile lock(lockPath(slot));
        lock.setStaleLockTime(0);
        if (!lock.tryLock(0)) continue;
        Recovery r;
        r.slot = slot;
        try {
            r.scene = loadScene(scenePath(slot).toStdString());
        } catch (const std::exception&) {
            continue;
        }
        QFile metaFile(metaPath(slot));
        if (metaFile.open(QIODevice::ReadOnly)) {
            const QJsonObject meta = QJsonDocument::fromJson(metaFile.readAll()).object();
            r.originalPath = meta.value(QStringLiteral("original")).toString();
            r.written = QDateTime::fromString(meta.value(QStringLiteral("written")).toString(),
                                              Qt::ISODate);
        }
        if (!r.written.isValid()) r.written = QFileInfo(scenePath(slot)).lastModified();
        found.push_back(std::move(r));
    }
    std::sort(found.begin(), found.end(),
              [](const Recovery& a, const Recovery& b) { return a.written > b.written; });
    return found;
}

void Autosave::discard(const Recovery& recovery) {
    QFile::remove(scenePath(recovery.slot));
    QFile::remove(metaPath(recovery.slot));
    QFile::remove(lockPath(recovery.slot));
}

}  // namespace whitted::ui
