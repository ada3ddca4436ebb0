// The editor's main window: viewport in the centre, outliner on the left, docks for the other panels, menus.
// It wires panels to the SceneDocument; it holds no scene data of its own.
#pragma once

#include <QMainWindow>

class QLabel;
class QTreeView;
class QSortFilterProxyModel;

namespace rl {

class SceneDocument;
class OutlinerModel;

class MainWindow : public QMainWindow {
    Q_OBJECT
public:
    explicit MainWindow(QWidget* parent = nullptr);
    ~MainWindow() override;

    SceneDocument* document() const { return m_document; }
    QTreeView* outlinerView() const { return m_outlinerView; }

    // Opens a scene file; shows the core's error (file, object, problem) in a message box when it fails.
    bool openFile(const QString& path);

protected:
    void closeEvent(QCloseEvent* event) override;

private:
    void createActions();
    void createDocks();
    void updateTitle();
    void updateStatus();

    SceneDocument* m_document = nullptr;
    OutlinerModel* m_outlinerModel = nullptr;
    QSortFilterProxyModel* m_outlinerProxy = nullptr;
    QTreeView* m_outlinerView = nullptr;
    QLabel* m_bodyCountLabel = nullptr;
};

} // namespace rl
