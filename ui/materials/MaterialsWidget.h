// The Materials panel: the scene's material library (presets and the scene's own materials) with an editor for the
// selected one, and the matrix of what each pair of materials in use gets at a contact. Every edit is one undo step
// (SetMaterialsCommand); drags of a slider or spin box merge into one.
//
// Deleting a material that bodies use moves those bodies to Default in the same undo step and says so. (Leaving them
// on a name the library no longer has would make the scene unsavable: .rlscene refuses bodies with unknown materials.)
// Renaming a material renames it on its bodies too. Presets keep their names and cannot be deleted; "Reset preset"
// brings back their built-in values.
#pragma once

#include "scene/MaterialDef.h"

#include <QWidget>

class QDoubleSpinBox;
class QLabel;
class QLineEdit;
class QSlider;
class QTableView;
class QToolButton;
class QGroupBox;

namespace rl {

class SceneDocument;
class MaterialLibraryModel;
class MaterialPairModel;
class MessageBar;

class MaterialsWidget : public QWidget {
    Q_OBJECT
public:
    explicit MaterialsWidget(SceneDocument* document, QWidget* parent = nullptr);

    MaterialLibraryModel* libraryModel() const { return m_library; }
    MaterialPairModel* pairModel() const { return m_pairs; }

    // The material the editor shows (empty when none).
    QString currentMaterial() const { return m_current; }
    void setCurrentMaterial(const QString& name);

    // The actions of the tool buttons; each pushes one undo command, or shows why it cannot.
    void addMaterial();
    void duplicateMaterial();
    void deleteMaterial();
    void resetPreset();

    // Stores material in place of the one called oldName, as one undo step (merging with the previous edit of the
    // same field of the same material when mergeId is not -1). Refused with a message when the material is invalid.
    bool applyMaterial(const QString& oldName, const MaterialDef& material, const QString& text, int mergeId = -1);

    // The last message shown to the user (a refusal or what an edit did); empty when none is shown.
    QString message() const;

private:
    void refreshEditor();
    void refreshButtons();
    void refreshPairs();
    void selectRow(int row);
    void editField(double value, double MaterialDef::*field, const QString& text, int mergeId);

    SceneDocument* m_document;
    MaterialLibraryModel* m_library;
    MaterialPairModel* m_pairs;
    QString m_current;
    int m_currentRow = 0;

    QTableView* m_table = nullptr;
    QToolButton* m_addButton = nullptr;
    QToolButton* m_duplicateButton = nullptr;
    QToolButton* m_deleteButton = nullptr;
    QToolButton* m_resetButton = nullptr;
    MessageBar* m_message = nullptr;

    QGroupBox* m_editor = nullptr;
    QLabel* m_kindLabel = nullptr;
    QLineEdit* m_name = nullptr;
    QDoubleSpinBox* m_density = nullptr;
    QDoubleSpinBox* m_friction = nullptr;
    QSlider* m_frictionSlider = nullptr;
    QDoubleSpinBox* m_restitution = nullptr;
    QSlider* m_restitutionSlider = nullptr;

    QTableView* m_pairTable = nullptr;
    QLabel* m_pairRules = nullptr;
    QLabel* m_pairNote = nullptr;
};

} // namespace rl
