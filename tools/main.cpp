// umbra: exact hard shadows with stencil shadow volumes.
#include <iostream>
#include <string>
#include <vector>

#include "image/partial_file.hpp"
#include "render/headless_context.hpp"
#include "tools/bench_command.hpp"
#include "tools/check_command.hpp"
#include "tools/huge_page_malloc.hpp"
#include "tools/render_command.hpp"
#include "tools/view_command.hpp"
#include "tools/volume_command.hpp"

namespace {

const char* const kUsage = R"(usage: umbra COMMAND [options]

Renders exact hard shadows with stencil shadow volumes.

commands:
  render SCENE -o OUT.png   render a scene headless to a PNG (see umbra render --help)
  check MESH...             is each mesh a closed 2-manifold, and if not, why
                            (see umbra check --help)
  view SCENE                an interactive window: the light orbits,
                            keys and mouse (see umbra view --help)
  volume SCENE -o OUT.obj   write a light's shadow volumes as a mesh to look at
                            (see umbra volume --help)
  bench [SCENES...]         shadow error against frame time for every method
                            (see umbra bench --help)

  umbra --help, umbra --version
)";

}  // namespace

int main(int argc, char** argv) {
  const std::vector<std::string> args(argv + 1, argv + argc);
  if (args.empty() || args[0] == "-h" || args[0] == "--help" || args[0] == "help") {
    std::cout << kUsage;
    return args.empty() ? 2 : 0;
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
  if (args[0] == "render") return umbra::run_render_command({args.begin() + 1, args.end()});
  if (args[0] == "check") return umbra::run_check_command({args.begin() + 1, args.end()});
  if (args[0] == "volume") return umbra::run_volume_command({args.begin() + 1, args.end()});
  if (args[0] == "bench") return umbra::run_bench_command({args.begin() + 1, args.end()});
  if (args[0] == "view") return umbra::run_view_command({args.begin() + 1, args.end()});
  std::cerr << "umbra: unknown command \"" << args[0] << "\"\n" << kUsage;
  return 2;
}
