// umbra: exact hard shadows with stencil shadow volumes.
#include <iostream>
#include <string>
#include <vector>

#include "image/partial_file.hpp"
#include "render/headless_context.hpp"
#include "tools/bench_command.hpp"
#include "tools/check_command.hpp"
#include "tools/command_line.hpp"
#include "tools/formats_command.hpp"
#include "tools/nearest_word.hpp"
#include "tools/huge_page_malloc.hpp"
#include "tools/render_command.hpp"
#include "tools/view_command.hpp"
#include "tools/volume_command.hpp"

namespace {

// The commands: each one's name, the arguments its line in the help shows,
// what it does, and what runs it. `umbra help NAME` is `umbra NAME --help`.
struct Command {
  const char* name;
  const char* arguments;
  const char* does;
  int (*run)(const std::vector<std::string>&);
};
const Command kCommands[] = {
    {"render", "MESH|SCENE|FOLDER... -o OUT", "a picture with exact shadows: a mesh file staged on a floor, a scene as\n"
                                              "written, a folder's meshes one picture each", umbra::run_render_command},
    {"check", "MESH|FOLDER...", "is each mesh a closed 2-manifold, and if not, why; --repair", umbra::run_check_command},
    {"view", "MESH|SCENE", "an interactive window: the light orbits, the camera follows the mouse", umbra::run_view_command},
    {"volume", "MESH|SCENE -o OUT.obj", "a light's shadow volumes as a mesh, to look at", umbra::run_volume_command},
    {"bench", "[SCENES...]", "shadow error against frame time for every method", umbra::run_bench_command},
    {"formats", "", "every mesh format umbra reads, and what reads it", umbra::run_formats_command},
};

std::string usage() {
  std::string text = R"(usage: umbra COMMAND [options]

Exact hard shadows from stencil shadow volumes, for any mesh file on its own
and for scenes of spheres, triangles and meshes.
Mesh files: umbra formats lists every format umbra reads.

  umbra render model.glb -o model.png    the model on a floor, with its shadow
  umbra render models/ -o pictures/      a picture of every mesh in a folder
  umbra check model.stl                  is it closed and manifold? if not, why
  umbra render scene.scene -o out.png    a scene file, as written

commands:
)";
  for (const Command& c : kCommands) {
    text += "  " + std::string(c.name) + " " + c.arguments + "\n";
    std::string does = c.does;
    for (size_t at = 0; at != std::string::npos;) {
      const size_t end = does.find('\n', at);
      text += "      " + does.substr(at, end == std::string::npos ? end : end - at) + "\n";
      at = end == std::string::npos ? end : end + 1;
    }
  }
  return umbra::usage_text(text) + R"(
  umbra help COMMAND (or umbra COMMAND --help) for a command's options
  umbra COMMAND --list-options: its options' names, one a line (for shell completion)
  umbra --list-options=markdown: every command's options as docs/options.md has them
  umbra --help, umbra --version
)";
}

// docs/options.md: every command's options as a Markdown table, each from
// its own definition (`umbra --list-options=markdown > docs/options.md`).
int print_options_doc() {
  std::cout << "# Options\n\n"
               "Every option of every command, as its `--help` gives it. This page is written by umbra itself from the "
               "options' definitions\n(`umbra --list-options=markdown > docs/options.md`), and a test fails until it is "
               "written again after an option changes.\n";
  for (const Command& c : kCommands) {
    std::cout << "\n## umbra " << c.name << (*c.arguments ? " " : "") << c.arguments << "\n\n" << std::flush;
    if (const int status = c.run({"--list-options=markdown"}); status != 0) return status;
    std::cout << std::flush;
  }
  return 0;
}

const Command* command_named(const std::string& name) {
  for (const Command& c : kCommands)
    if (name == c.name) return &c;
  return nullptr;
}

// "unknown command "rendr" (did you mean render?)".
std::string unknown_command(const std::string& name) {
  std::vector<std::string> names;
  for (const Command& c : kCommands) names.push_back(c.name);
  return "umbra: unknown command \"" + name + "\"" + umbra::did_you_mean(name, names) + "\n";
}

}  // namespace

int main(int argc, char** argv) {
  const std::vector<std::string> args(argv + 1, argv + argc);
  if (args.empty() || args[0] == "-h" || args[0] == "--help" || (args[0] == "help" && args.size() == 1)) {
    std::cout << usage();
    return args.empty() ? 2 : 0;
  }
  if (args[0] == "--list-options=markdown") return print_options_doc();
  if (args[0] == "help") {
    const Command* command = command_named(args[1]);
    if (!command) {
      std::cerr << unknown_command(args[1]) << "(see umbra --help)\n";
      return 2;
    }
    return command->run({"--help"});
  }
  umbra::restart_with_huge_page_malloc(argv);  // before any allocation worth the name
  umbra::remove_partial_files_on_signals();
  if (args[0] == "--version") {
    std::cout << "umbra " << UMBRA_VERSION << "\n";
    // What umbra render would draw with: the platform --gl auto picks.
    try {
      const umbra::HeadlessContext context(16, 16);
      std::cout << "headless OpenGL: " << context.description() << "\n";
    } catch (const std::exception& e) {
      std::cout << "headless OpenGL: none (" << e.what() << ")\n";
    }
    std::cout << "memory: " << umbra::malloc_pages_description(umbra::current_malloc_environment()) << "\n";
    return 0;
  }
  if (const Command* command = command_named(args[0])) return command->run({args.begin() + 1, args.end()});
  std::cerr << unknown_command(args[0]) << "(see umbra --help)\n";
  return 2;
}
