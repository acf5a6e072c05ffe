// libFuzzer target: FBX, glTF and Collada takes (parseSceneTake: assimp's reading, then our
// conversion of its scene to a skeleton and motion) and the puppet import every take runs after
// it. The first byte chooses the format ('f' FBX, 'b' glTF binary, 'g' glTF text, 'd' Collada;
// any other byte by its value), the rest is the file. assimp itself is Debian's shared library,
// not instrumented: the sanitizers and the allocation limits still see everything it does.
#include "fuzz/fuzz_support.h"

#include "analysis/io/bvh_import.h"
#include "analysis/io/scene_take.h"
#include "analysis/io/take_reader.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
    using namespace bunraku;
    if (size < 1) return 0;
    const char* extensions[] = {".fbx", ".glb", ".gltf", ".dae"};
    const int index = data[0] == 'f' ? 0 : data[0] == 'b' ? 1 : data[0] == 'g' ? 2 : data[0] == 'd' ? 3 : data[0] % 4;
    const std::string extension = extensions[index];
    auto scene = analysis::io::parseSceneTake(fuzz::textOf(data + 1, size - 1), extension, "fuzz-input" + extension);
    if (!scene) {
        fuzz::expect(fuzz::namesSource(scene.error().message), "a scene take error names the file");
        fuzz::expect(scene.error().message.find('\n') == std::string::npos, "a scene take error is one line");
        return 0;
    }
    fuzz::expect(scene->bvh.motion.values.rows() >= 1, "a scene take has a frame");
    auto take = analysis::io::bvhToPuppetTake(scene->bvh, analysis::io::sceneBvhOptions({}));
    if (take) fuzz::expect(analysis::validateTake(*take).ok(), "an imported scene take is valid");
    return 0;
}
