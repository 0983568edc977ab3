#include "cli/operation.h"

#include <algorithm>

namespace swarf::cli {

namespace {

std::vector<Operation>& registry() {
  static std::vector<Operation> ops;
  return ops;
}

}  // namespace

OperationRegistrar::OperationRegistrar(Operation op) {
  auto& ops = registry();
  ops.push_back(std::move(op));
  std::sort(ops.begin(), ops.end(),
            [](const Operation& a, const Operation& b) { return a.name < b.name; });
}

const std::vector<Operation>& operations() {
  return registry();
}

const Operation* find_operation(const std::string& name) {
  for (const Operation& op : registry())
    if (op.name == name) return &op;
  return nullptr;
}

}  // namespace swarf::cli
