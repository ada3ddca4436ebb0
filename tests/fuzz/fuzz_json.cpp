// libFuzzer target for the JSON reader and the .rlscene reader: no input may crash, hang or leak, and whatever
// parses must write and parse back to an equal document.
#include "io/Json.h"
#include "io/SceneJson.h"

#include <cstdint>
#include <cstdlib>
#include <string_view>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    const std::string_view text(reinterpret_cast<const char*>(data), size);
    rl::Result<rl::JsonValue> doc = rl::parseJson(text, "fuzz.json");
    if (doc) {
        for (int indent : {0, 2}) {
            rl::Result<rl::JsonValue> again = rl::parseJson(rl::writeJson(*doc, indent), "again.json");
            if (!again || !(*again == *doc))
                std::abort();
        }
    }
    // A directory that does not exist, so relative "obj" paths fail fast instead of reading the disk.
    rl::Result<rl::Scene> scene = rl::readSceneJson(text, "/nonexistent-fuzz-dir/scene.rlscene");
    if (scene) {
        rl::Result<rl::Scene> again = rl::readSceneJson(rl::writeSceneJson(*scene), scene->sourcePath);
        if (!again || !(*again == *scene))
            std::abort();
    }
    return 0;
}
