// File > Export: where to write, which format, and for CSV which bodies (all or the selection) and which frames.
#pragma once

#include "analysis/ExportJob.h"

#include <QDialog>
#include <QList>

class QComboBox;
class QLineEdit;
class QRadioButton;
class QSpinBox;
class QLabel;
class QGroupBox;

namespace rl {

class ExportDialog : public QDialog {
    Q_OBJECT
public:
    // frameCount and bodyCount describe the bake; selection holds the editor's selected bodies.
    // hasVelocities: false for a bake read from a .bake file (its CSV leaves the velocity fields empty).
    ExportDialog(ExportRequest::Format format, size_t frameCount, size_t bodyCount, double fps, bool hasVelocities,
                 const QList<int>& selection, const QString& suggestedPath, QWidget* parent = nullptr);

    ExportRequest request() const;

    void accept() override;

private:
    void updateState();
    void browse();

    size_t m_frameCount;
    size_t m_bodyCount;
    double m_fps;
    bool m_hasVelocities;
    QList<int> m_selection;
    QComboBox* m_format = nullptr;
    QLineEdit* m_path = nullptr;
    QGroupBox* m_csvGroup = nullptr;
    QRadioButton* m_allBodies = nullptr;
    QRadioButton* m_selectedBodies = nullptr;
    QRadioButton* m_allFrames = nullptr;
    QRadioButton* m_frameRange = nullptr;
    QSpinBox* m_firstFrame = nullptr;
    QSpinBox* m_lastFrame = nullptr;
    QLabel* m_summary = nullptr;
};

} // namespace rl
