// The pre-flight check's findings (core/analysis/Preflight) as a dialog: one row per finding with the body, what was
// found and the suggested fix. Before a bake it asks "Bake anyway" / "Cancel" and offers to stop asking for this
// scene; from Analysis > Pre-flight check it only shows the list.
#pragma once

#include "analysis/Preflight.h"

#include <QDialog>

#include <vector>

class QCheckBox;
class QLabel;
class QTreeWidget;

namespace rl {

class PreflightDialog : public QDialog {
    Q_OBJECT
public:
    enum class Mode { ConfirmBake, Show };

    PreflightDialog(const Scene& scene, std::vector<PreflightFinding> findings, Mode mode, QWidget* parent = nullptr);

    const std::vector<PreflightFinding>& findings() const { return m_findings; }
    // ConfirmBake: the user ticked "Don't show again for this scene".
    bool dontShowAgain() const;

    // The finding in the user's words (translated), and the fix.
    static QString describe(const Scene& scene, const PreflightFinding& finding);
    static QString suggestFix(const Scene& scene, const PreflightFinding& finding);
    static QString kindTitle(PreflightKind kind);

signals:
    // A row was clicked: its body (to select it in the editor).
    void bodyActivated(int body);

private:
    std::vector<PreflightFinding> m_findings;
    QTreeWidget* m_list = nullptr;
    QCheckBox* m_dontShow = nullptr;
    QLabel* m_fix = nullptr;
};

} // namespace rl
