#include "problem_options.hpp"

#include <vector>

#include "cartan/api/json_io.hpp"

namespace cartan::cli {

void add_problem_options(CLI::App& command, ProblemFlags& flags) {
  command.add_option("--problem", flags.problem_file, "JSON problem file (keys as the flags; flags override it)");
  for (const auto& field : problem_fields()) {
    if (field.key == "output") continue;  // each command has its own --output
    std::visit(
        [&](auto member) {
          using T = std::decay_t<decltype(flags.spec.*member)>;
          if constexpr (std::is_same_v<T, std::vector<double>>) {
            command.add_option(field.flag(), flags.lists[field.key], field.help);
          } else {
            command.add_option(field.flag(), flags.spec.*member, field.help);
          }
        },
        field.member);
  }
}

ProblemSpec problem_from(const CLI::App& command, ProblemFlags& flags) {
  std::vector<const ProblemField*> given;
  for (const auto* opt : command.get_options()) {
    if (opt->count() == 0) continue;
    for (const auto& field : problem_fields()) {
      if (opt->check_lname(field.flag().substr(2))) given.push_back(&field);
    }
  }
  for (const auto* field : given) {  // list errors first, naming the flag
    if (const auto* list = std::get_if<std::vector<double> ProblemSpec::*>(&field->member)) {
      flags.spec.**list = io::parse_list(flags.lists.at(field->key), field->key);
    }
  }
  ProblemSpec spec;
  if (!flags.problem_file.empty()) {
    apply_json(spec, io::read_json_file(flags.problem_file, "cartan " + command.get_name() + ": --problem"));
  }
  for (const auto* field : given) {  // flags override the file
    std::visit([&](auto member) { spec.*member = flags.spec.*member; }, field->member);
    spec.given.push_back(field->key);
  }
  return spec;
}

}  // namespace cartan::cli
