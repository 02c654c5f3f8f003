#include "strahl/ch07/builder_scenes.hpp"
#include "strahl/procedural.hpp"
#include "strahl/program.hpp"
#include <utility>

namespace strahl::ch07 {

std::string builder_scene_choice(const std::string& scene_option, bool quick) {
    if (quick) return "quick";
    for (const char* ok : {"all", "teapot", "stadium", "soup", "bunny", "sponza"})
        if (scene_option == ok) return scene_option;
    throw usage_error("--scene must be stadium, soup, bunny, sponza, teapot or all, not '" + scene_option + "'");
}

std::vector<scene> builder_scenes(const std::string& choice) {
    const bool quick = choice == "quick", all = choice == "all";
    std::vector<scene> scenes;
    if (choice == "teapot" || quick) scenes.push_back(builtin_scene("teapot"));
    if (all || choice == "stadium") scenes.push_back(builtin_scene("teapot_stadium"));
    if (all || choice == "soup" || quick) scenes.push_back(mesh_scene("soup", random_soup(quick ? 20000 : 200000, 1)));
    for (const auto& [name, file] : {std::pair{"bunny", "bunny.ply"}, std::pair{"sponza", "sponza.obj"}}) {
        if (!all && choice != name) continue;
        if (auto s = load_shared_mesh(file, name)) scenes.push_back(std::move(*s));
    }
    return scenes;
}

}  // namespace strahl::ch07
