#include "io/BakeLoad.h"

#include "io/ObjReader.h"
#include "io/SceneImport.h"
#include "scene/BodyProperties.h"

namespace rl {

Result<LoadedBake> loadBake(const std::string& path) {
    LoadedBake loaded;
    Result<Bake> bake = readBakeFile(path, &loaded.info);
    if (!bake)
        return bake.error();
    loaded.bake = std::move(bake).value();
    const std::string& objText = loaded.bake.sceneObjText();
    if (objText.empty())
        return loaded;
    Result<ObjFile> obj = readObj(objText, path);
    if (!obj)
        return obj.error();
    loaded.scene = sceneFromObjects(obj.value());
    loaded.scene.sourcePath = path;
    loaded.scene.sourceObjText = objText;
    if (loaded.scene.bodies.size() != loaded.bake.bodyCount())
        return loaded; // the OBJ part does not describe these bodies one to one; keep the vertex means
    for (size_t i = 0; i < loaded.scene.bodies.size(); ++i) {
        Result<BodyProperties> props = computeBodyProperties(loaded.scene, loaded.scene.bodies[i]);
        if (!props) {
            Error e = props.error();
            e.file = path;
            return e;
        }
        loaded.bake.body(i).anchor = loaded.scene.bodies[i].anchor;
        loaded.bake.rebaseVertexMeanOffset(i, props->vertexMean - props->com);
    }
    loaded.centred = true;
    return loaded;
}

} // namespace rl
