// Running an export as the editor's Export Image dialog does, and waiting for
// its finished message: shared by the GUI tests that export.
#pragma once

#include <QObject>
#include <QString>
#include <QTest>

#include "editor/export_job.h"

namespace whitted::ui {

struct ExportOutcome {
    bool finished = false;  // within the timeout
    bool ok = false;
    QString message;
};

inline ExportOutcome exportAndWait(const Scene& scene, const ExportSettings& settings,
                                   int timeoutMs = 30000) {
    PlanMemo plans;  // its own: each export plans, as the first in a session does
    ExportJob job(scene, settings, plans);
    ExportOutcome outcome;
    // &job as context: queued to this thread (finished comes from the export thread).
    QObject::connect(&job, &ExportJob::finished, &job, [&](bool success, const QString& text) {
        outcome.finished = true;
        outcome.ok = success;
        outcome.message = text;
    });
    job.start();
    outcome.finished = QTest::qWaitFor([&] { return outcome.finished; }, timeoutMs);
    return outcome;
}

}  // namespace whitted::ui
