// The editor's main window: viewport in the centre, outliner on the left, docks for the other panels, menus.
// It owns the document, the viewport, the outliner and the inspector, and keeps the selection. Each area of the
// editor is a controller (ui/<area>/…Controller) that adds its own menus, toolbars and docks to the window; the
// window holds no scene data of its own.
#pragma once

#include <QMainWindow>
#include <QPointer>
#include <QWindow>

#include <memory>

class QLabel;
class QMenu;
class QTreeView;
class QSortFilterProxyModel;

namespace rl {

class SceneDocument;
class InspectorWidget;
class OutlinerModel;
class ScenePresenter;
class Viewport;
class FileController;
class EditController;
class SettingsController;
class SimulationController;
class AnalysisController;
class OverlayController;

class MainWindow : public QMainWindow {
    Q_OBJECT
public:
    // The menu bar in order. The window creates the menus; controllers fill them.
    enum class Menu { File, Export, Edit, Add, View, Simulation, Analysis, Window, Help };

    explicit MainWindow(QWidget* parent = nullptr);
    ~MainWindow() override;

    SceneDocument* document() const { return m_document; }
    QTreeView* outlinerView() const { return m_outlinerView; }
    Viewport* viewport() const { return m_viewport; }
    ScenePresenter* presenter() const { return m_presenter.get(); }
    InspectorWidget* inspector() const { return m_inspector; }
    QMenu* menu(Menu which) const;

    FileController* files() const { return m_files; }
    EditController* edit() const { return m_edit; }
    SettingsController* settings() const { return m_settings; }
    SimulationController* simulation() const { return m_simulation; }
    AnalysisController* analysis() const { return m_analysis; }
    OverlayController* overlays() const { return m_overlays; }

    // Selected body indices, in ascending order. The viewport and the outliner always show the same selection.
    QList<int> selectedBodies() const { return m_selection; }
    void setSelectedBodies(const QList<int>& bodies);

    // Opens a scene (any format the core reads) or a .bake; shows the core's error (file, object, problem) in a
    // message box when it fails.
    bool openFile(const QString& path);

    // The window's first geometry, used while no geometry is saved: all of a small screen's available area, 90 % of
    // a larger one's, centred on it.
    static QRect firstGeometry(const QRect& available);

signals:
    void selectionChanged(const QList<int>& bodies);
    // The viewport went back to the document's edit pose (after any scene change).
    void viewportRebuilt();

protected:
    void closeEvent(QCloseEvent* event) override;
    void showEvent(QShowEvent* event) override;
    bool eventFilter(QObject* watched, QEvent* event) override;
    void dragEnterEvent(QDragEnterEvent* event) override;
    void dropEvent(QDropEvent* event) override;

private:
    void createMenus();
    void createLanguageMenu();
    void createDocks();
    void updateTitle();
    void updateStatus();
    void rebuildViewport();
    void syncOutlinerSelection();

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
    QList<QMenu*> m_menus; // indexed by Menu
    FileController* m_files = nullptr;
    EditController* m_edit = nullptr;
    SettingsController* m_settings = nullptr;
    SimulationController* m_simulation = nullptr;
    AnalysisController* m_analysis = nullptr;
    OverlayController* m_overlays = nullptr;
    QList<int> m_selection;
    bool m_syncingSelection = false;
    bool m_restoredGeometry = false;
    bool m_shownOnce = false;
    QPointer<QWindow> m_lastFocusWindow; // the last of our windows that had the keyboard
};

} // namespace rl
