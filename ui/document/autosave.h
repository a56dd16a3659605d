// Crash recovery: unsaved edits are copied to a recovery file shortly after
// each burst of edits, and a later start finds the copies that a crashed (or
// killed) editor left behind.
//
// Each running editor owns one recovery slot in the recovery directory:
// <id>.json (the scene, written atomically), <id>.meta (the file it belongs to,
// when it was written) and <id>.lock, a QLockFile held while the editor runs.
// A slot whose lock can be taken belongs to an editor that is gone: that is a
// recovery to offer. Saving, or discarding the changes, empties the slot; a
// normal exit removes it.
#pragma once

#include <QDateTime>
#include <QLockFile>
#include <QObject>
#include <QString>
#include <QTimer>

#include <memory>
#include <vector>

#include "scene/scene.h"

namespace whitted::ui {

class SceneDocument;

// What a dead editor left.
struct Recovery {
    QString slot;          // the slot's path without extension
    QString originalPath;  // the scene file the edits belong to; empty for Untitled
    QDateTime written;     // when the recovery copy was written
    Scene scene;
};

class Autosave : public QObject {
    Q_OBJECT
  public:
    // `directory` is created if needed; defaultDirectory() when empty.
    Autosave(SceneDocument* doc, QString directory = {}, QObject* parent = nullptr);
    ~Autosave() override;  // a normal exit: the slot is removed

    // Milliseconds from the last edit of a burst to the copy (default 2000).
    void setDelay(int ms) { timer_.setInterval(ms); }
    QString directory() const { return dir_; }
    QString slotPath() const { return slot_; }  // this editor's slot, without extension

    // The slots of editors that are no longer running, newest first. Slots that
    // cannot be read are skipped (and left for a human to look at).
    static std::vector<Recovery> orphans(const QString& directory);
    // Removes a slot's files (after restoring or discarding it).
    static void discard(const Recovery& recovery);

    // $WHITTED_RECOVERY_DIR, else QStandardPaths' app data location + "/recovery".
    static QString defaultDirectory();

  signals:
    // A recovery copy was written (tests wait for it); `error` is empty on success.
    void written(const QString& error);

  private:
    void onSceneChanged();
    void writeNow();
    void clear();

    SceneDocument* doc_;
    QString dir_;
    QString slot_;
    std::unique_ptr<QLockFile> lock_;
    QTimer timer_;
};

}  // namespace whitted::ui
