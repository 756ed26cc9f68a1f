#include "command_registry.hpp"

#include <algorithm>

namespace molmesh::cli {
namespace {

std::vector<RegisteredCommand>& registry() {
  static std::vector<RegisteredCommand> commands;
  return commands;
}

}  // namespace

CommandRegistration::CommandRegistration(std::string name, CommandAdder add) {
  registry().push_back({std::move(name), std::move(add)});
}

std::vector<RegisteredCommand> registered_commands() {
  auto commands = registry();
  std::sort(commands.begin(), commands.end(),
            [](const auto& a, const auto& b) { return a.name < b.name; });
  return commands;
}

}  // namespace molmesh::cli
