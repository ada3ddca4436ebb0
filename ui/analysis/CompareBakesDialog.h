// Analysis > Compare bakes: the current bake against a .bake file, or two files (core/analysis/BakeDiff). Shows the
// first diverging frame and a sortable per-body table of the largest differences; clicking a row selects the body.
#pragma once

#include "analysis/BakeDiff.h"

#include <QAbstractTableModel>
#include <QDialog>

#include <functional>
#include <memory>

class QDoubleSpinBox;
class QLabel;
class QLineEdit;
class QRadioButton;
class QSortFilterProxyModel;
class QTableView;

namespace rl {

// One row per body: index, name, first diverging frame, largest position delta (mm) and its frame, largest
// rotation delta (degrees) and its frame. Sorting uses the numbers (SortRole), not the display text.
class BakeDiffModel : public QAbstractTableModel {
    Q_OBJECT
public:
    enum Column {
        BodyColumn,
        NameColumn,
        FirstFrameColumn,
        PositionColumn,
        PositionFrameColumn,
        RotationColumn,
        RotationFrameColumn,
        ColumnCount
    };
    static constexpr int SortRole = Qt::UserRole + 1;
    static constexpr int BodyIndexRole = Qt::UserRole + 2;

    using QAbstractTableModel::QAbstractTableModel;
    void setResult(const BakeDiffResult& result);
    const BakeDiffResult& result() const { return m_result; }

    int rowCount(const QModelIndex& parent = {}) const override;
    int columnCount(const QModelIndex& parent = {}) const override;
    QVariant data(const QModelIndex& index, int role) const override;
    QVariant headerData(int section, Qt::Orientation orientation, int role) const override;

private:
    BakeDiffResult m_result;
};

class CompareBakesDialog : public QDialog {
    Q_OBJECT
public:
    // currentBake gives the editor's bake (null when there is none).
    CompareBakesDialog(std::function<std::shared_ptr<const Bake>()> currentBake, QWidget* parent = nullptr);

    // Compares with the dialog's current choices; on failure shows the reason in the summary and returns false.
    bool compare();
    void setFileA(const QString& path);
    void setFileB(const QString& path);
    void setUseCurrentBake(bool useCurrent);

    BakeDiffModel* model() const { return m_model; }
    QTableView* table() const { return m_table; }
    QString summary() const;

signals:
    void bodyActivated(int body);

protected:
    void showEvent(QShowEvent* event) override;

private:
    std::shared_ptr<const Bake> load(const QString& path, QString* error) const;
    void updateSources();

    std::function<std::shared_ptr<const Bake>()> m_currentBake;
    QRadioButton* m_useCurrent = nullptr;
    QRadioButton* m_useFileA = nullptr;
    QLineEdit* m_fileA = nullptr;
    QLineEdit* m_fileB = nullptr;
    QDoubleSpinBox* m_positionTolerance = nullptr;
    QDoubleSpinBox* m_rotationTolerance = nullptr;
    QLabel* m_summary = nullptr;
    BakeDiffModel* m_model = nullptr;
    QSortFilterProxyModel* m_proxy = nullptr;
    QTableView* m_table = nullptr;
};

} // namespace rl
