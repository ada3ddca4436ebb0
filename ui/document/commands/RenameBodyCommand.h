// Undo command that renames one body: a SetBodyCommand with only the name changed and a "Rename" text.
// Consecutive renames of the same body merge (SetBodyNameId).
#pragma once

#include "document/commands/SetBodyCommand.h"

namespace rl {

class RenameBodyCommand : public SetBodyCommand {
public:
    RenameBodyCommand(SceneDocument* document, int index, const QString& name, QUndoCommand* parent = nullptr);
};

} // namespace rl
