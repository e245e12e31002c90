// The planning commands on the `swarm` command line beyond `run`: `swarm tour`, `swarm clean`,
// `swarm experiment tour` and `swarm experiment clean` (offline: tour_command.hpp,
// clean_command.hpp, offline_experiments.hpp), and the live task experiments `swarm experiment
// cover` and `swarm experiment mapf-live` (experiment_tasks.hpp). swarm_main.cpp makes one OfflineCommands after its own subcommands and
// asks it after parsing:
//
//   OfflineCommands offline(app, *experiment_cmd);
//   app.parse(argc, argv);
//   if (auto status = offline.run(std::cout, std::cerr)) return *status;
#pragma once

#include <memory>
#include <optional>
#include <ostream>

namespace CLI {
class App;
}

namespace swarm::tools {

class OfflineCommands {
 public:
  OfflineCommands(CLI::App& app, CLI::App& experiment);
  ~OfflineCommands();
  OfflineCommands(const OfflineCommands&) = delete;
  OfflineCommands& operator=(const OfflineCommands&) = delete;

  // The exit status of the offline command that was parsed; nullopt if none was.
  std::optional<int> run(std::ostream& out, std::ostream& err) const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace swarm::tools
