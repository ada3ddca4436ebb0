// Long text outputs (a .bake's frames, CSV rows) formatted in blocks on several threads and written in block order,
// so the bytes are the same for any number of threads. Number formatting is most of an export's time.
#pragma once

#include <cstddef>
#include <functional>
#include <string>

namespace rl {

// Calls format(block, text) for blocks 0 .. count - 1, each into an emptied string, on `threads` threads, and
// write(text) for each block in block order on the calling thread. At most 2 x threads blocks are held at once, so
// memory stays flat however long the output is. write() returning false stops the work: the blocks after it are
// neither formatted nor written, and the call returns false. With threads <= 1 (or one block) everything runs on
// the calling thread. format() may only read what is shared. An exception from write() stops the work the same way;
// one from format() for block k stops it as on one thread: blocks 0 .. k - 1 are still written and nothing after
// (of several failing blocks, the lowest one counts). The exception is rethrown on the calling thread once every
// worker has finished.
bool writeBlocksInOrder(size_t count, int threads, const std::function<void(size_t block, std::string& text)>& format,
                        const std::function<bool(const std::string& text)>& write);

// How many frames of `bodies` bodies make a block of writeBlocksInOrder() for the file writers: about 8,192 lines,
// some 0.4-1 MB of text, large enough that a block's hand-over costs nothing beside its formatting.
size_t framesPerBlock(size_t bodies);

} // namespace rl
