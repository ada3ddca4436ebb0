// Read-outs that change with every frame (the timeline's time, the simulation status) must not re-lay out the
// window. A QLabel whose text changes asks its parents for a new layout, which reaches the main window's dock layout
// and costs a second full composition of the window after the frame was shown (under a software GL, about as much
// as drawing 5,000 bodies). A label with a fixed size does not ask, so these labels get one: as wide as the widest
// text shown so far, growing when a wider one comes and never shrinking.
#pragma once

class QLabel;
class QString;

namespace rl {

void setStableText(QLabel* label, const QString& text);

} // namespace rl
