#pragma once
// The commands' options, each defined once and called by every command that
// takes it: the parser (command_options.hpp), the values options take
// (option_values.hpp), how a picture is drawn (render_options.hpp), how a
// mesh file is read and staged (staging_options.hpp), what an output may be
// named (output_paths.hpp) and the --help texts (usage_text.hpp). A command
// includes this one header for all of them.

#include "tools/command_options.hpp"
#include "tools/option_values.hpp"
#include "tools/output_paths.hpp"
#include "tools/render_options.hpp"
#include "tools/staging_options.hpp"
#include "tools/usage_text.hpp"
