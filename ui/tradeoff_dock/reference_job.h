// Pin as Reference's converged reference: core's renderReference (the scene in
// double, at many samples per pixel, deep enough for its mirrors and glass) on
// a thread of its own, so the editor keeps working while it renders. Cancel
// (or destroying the job) stops it within a tile row of work.
#pragma once

#include <QObject>
#include <QString>

#include <atomic>
#include <memory>
#include <thread>

#include "image/image.h"
#include "scene/scene.h"

namespace whitted::ui {

struct ConvergedReference {
    std::shared_ptr<const Image> image;  // at the scene's render size
    RenderSettings settings;             // what it was rendered with
    double seconds = 0.0;
};

class ReferenceJob : public QObject {
    Q_OBJECT
  public:
    ReferenceJob(const Scene& scene, int samples, QObject* parent = nullptr);
    ~ReferenceJob() override;  // cancels and waits for the thread

    void start();
    const Scene& scene() const { return scene_; }
    int samples() const { return samples_; }

  signals:
    // Exactly once unless cancelled; `error` is core's message when it failed.
    void finished(const whitted::ui::ConvergedReference& reference, const QString& error);

  private:
    void run();

    Scene scene_;
    int samples_;
    std::atomic<bool> cancelled_{false};
    std::thread thread_;
};

}  // namespace whitted::ui

Q_DECLARE_METATYPE(whitted::ui::ConvergedReference)
