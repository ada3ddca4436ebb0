// The inspector panel: the selected bodies' editable definition and their computed properties (mass, inertia, hull).
// Every row is a getter (refresh) plus a setter that only pushes an undo command; multi-selection edits are one step.
#pragma once

#include "scene/BodyDef.h"

#include <QList>
#include <QWidget>

#include <array>
#include <functional>

class QCheckBox;
class QComboBox;
class QDoubleSpinBox;
class QLabel;
class QLineEdit;

namespace rl {

class SceneDocument;
class MessageBar;

class InspectorWidget : public QWidget {
    Q_OBJECT
public:
    explicit InspectorWidget(SceneDocument* document, QWidget* parent = nullptr);

    QList<int> selection() const { return m_selection; }
    void setSelection(const QList<int>& bodies);

    // Shown in place of a value that differs between the selected bodies.
    static QString mixedText();

    // Why the last edit was refused (an override out of range), or an empty string.
    QString message() const;

private:
    // An optional override: a check box that enables it and the spin box holding the value.
    struct OverrideRow {
        QCheckBox* enabled = nullptr;
        QDoubleSpinBox* value = nullptr;
    };
    using Vec3Row = std::array<QDoubleSpinBox*, 3>;

    void refresh();
    void refreshComputed();
    // Applies edit to every selected body as one undo command (merging with the previous one of the same mergeId).
    void applyEdit(const QString& text, int mergeId, const std::function<void(BodyDef&)>& edit);

    QDoubleSpinBox* makeSpinBox(const QString& objectName, double min, double max, int decimals, double step,
                                const QString& suffix);
    // An override's value must be above min (or at least min when minInclusive); the spin box reaches below min
    // only for its "mixed" sentinel and for typing slips, which are refused with a message.
    OverrideRow makeOverride(const QString& objectName, double max, int decimals, double step, const QString& suffix,
                             const QString& text, int mergeId, std::optional<Real> BodyDef::*field,
                             const QString& rangeMessage, bool zeroAllowed);
    Vec3Row makeVec3(const QString& objectName, double range, int decimals, double step, const QString& suffix,
                     const QString& text, int mergeId, const std::function<void(BodyDef&, int, double)>& set);

    static void showValue(QDoubleSpinBox* box, std::optional<double> value);
    static void showOverride(OverrideRow row, const std::vector<std::optional<Real>>& values,
                             std::optional<double> fallback);

    SceneDocument* m_document;
    QList<int> m_selection;
    QWidget* m_scroll = nullptr;
    QWidget* m_content = nullptr;
    QLabel* m_emptyLabel = nullptr;
    MessageBar* m_message = nullptr;

    QLineEdit* m_name = nullptr;
    QCheckBox* m_anchor = nullptr;
    QComboBox* m_material = nullptr;
    OverrideRow m_density;
    OverrideRow m_mass;
    OverrideRow m_friction;
    OverrideRow m_restitution;
    Vec3Row m_position{};
    Vec3Row m_rotation{};
    Vec3Row m_velocity{};
    Vec3Row m_angularVelocity{};

    QLabel* m_volumeLabel = nullptr;
    QLabel* m_massLabel = nullptr;
    QLabel* m_comLabel = nullptr;
    QLabel* m_inertiaLabel = nullptr;
    QLabel* m_hullLabel = nullptr;
    QLabel* m_warningsLabel = nullptr;
};

} // namespace rl
