// A message line inside a panel: why an edit was refused (error) or what an edit also did (info). It stays until the
// next message or until the user closes it, so a refusal is never missed the way a status-bar message can be.
#pragma once

#include <QFrame>

class QLabel;
class QToolButton;

namespace rl {

class MessageBar : public QFrame {
    Q_OBJECT
public:
    enum class Kind { Info, Error };

    explicit MessageBar(QWidget* parent = nullptr);

    void showMessage(const QString& text, Kind kind);
    void clearMessage();
    QString text() const;
    Kind kind() const { return m_kind; }

private:
    QLabel* m_label;
    QToolButton* m_close;
    Kind m_kind = Kind::Info;
};

} // namespace rl
