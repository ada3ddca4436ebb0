// The editor's main window: viewport in the centre, outliner on the left, docks for the other panels, menus.
// It wires panels to the SceneDocument; it holds no scene data of its own.
#pragma once

#include <QMainWindow>

#include <memory>

class QLabel;
class QTreeView;
class QSortFilterProxyModel;

namespace rl {

class SceneDocument;
class InspectorWidget;
class OutlinerModel;
class ScenePresenter;
class Viewport;

class MainWindow : public QMainWindow {
    Q_OBJECT
public:
    explicit MainWindow(QWidget* parent = nullptr);
    ~MainWindow() override;

    SceneDocument* document() const { return m_document; }
    QTreeView* outlinerView() const { return m_outlinerView; }
    Viewport* viewport() const { return m_viewport; }
    InspectorWidget* inspector() const { return m_inspector; }
    // Selected body indices, in ascending order. The viewport and the outliner always show the same selection.
    QList<int> selectedBodies() const { return m_selection; }
    void setSelectedBodies(const QList<int>& bodies);

    // Opens a scene file; shows the core's error (file, object, problem) in a message box when it fails.
    bool openFile(const QString& path);

signals:
    void selectionChanged(const QList<int>& bodies);

protected:
    void closeEvent(QCloseEvent* event) override;
    bool eventFilter(QObject* watched, QEvent* event) override;

private:
    void createActions();
    void createDocks();
    void updateTitle();
    void updateStatus();
    void rebuildViewport();
    void syncOutlinerSelection();
    void createEditActions();
    void deleteSelection();
    void toggleAnchor();

    SceneDocument* m_document = nullptr;
    OutlinerModel* m_outlinerModel = nullptr;
    QSortFilterProxyModel* m_outlinerProxy = nullptr;
    QTreeView* m_outlinerView = nullptr;
    QLabel* m_bodyCountLabel = nullptr;
    QLabel* m_selectionLabel = nullptr;
    QLabel* m_frameTimeLabel = nullptr;
    Viewport* m_viewport = nullptr;
    InspectorWidget* m_inspector = nullptr;
    std::unique_ptr<ScenePresenter> m_presenter;
    QList<int> m_selection;
    bool m_syncingSelection = false;
};

} // namespace rl
