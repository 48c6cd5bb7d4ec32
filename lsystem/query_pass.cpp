#include "lsystem/query_pass.hpp"

#include "lsystem/turtle_core.hpp"

namespace fspm::lsystem {
namespace {

class QueryVisitor {
 public:
  QueryVisitor(ModuleString& s, std::vector<EnvironmentQuery>& queries,
               std::vector<std::size_t>& where)
      : s_(s), queries_(queries), where_(where) {}
  void forward(const Eigen::Vector3d&, const Eigen::Vector3d&, double, detail::Frame&) {}
  void polygon_begin(const detail::Frame&) {}
  void vertex(const Eigen::Vector3d&) {}
  void polygon_end(const detail::Frame&) {}
  void surface(double, const detail::Frame&) {}
  void query(std::size_t i, detail::Action a, const detail::Frame& f) {
    if (a == detail::Action::kCommunicate) {
      EnvironmentQuery q;
      q.position = f.position;
      q.heading = f.heading;
      q.left = f.left;
      q.up = f.up;
      const auto p = s_.parameters(i);
      q.parameters.assign(p.begin(), p.end());
      queries_.push_back(std::move(q));
      where_.push_back(i);
      return;
    }
    const Eigen::Vector3d& v = a == detail::Action::kQueryP   ? f.position
                               : a == detail::Action::kQueryH ? f.heading
                               : a == detail::Action::kQueryU ? f.up
                                                              : f.left;
    auto p = s_.parameters(i);
    for (std::size_t k = 0; k < p.size() && k < 3; ++k) p[k] = v[static_cast<int>(k)];
  }

 private:
  ModuleString& s_;
  std::vector<EnvironmentQuery>& queries_;
  std::vector<std::size_t>& where_;
};

}  // namespace

void fill_query_modules(const LSystem& system, ModuleString& s, const TurtleSettings& settings,
                        OpenEnvironment* environment) {
  const auto actions = detail::action_table(system.symbols);
  std::vector<EnvironmentQuery> queries;
  std::vector<std::size_t> where;
  QueryVisitor visitor(s, queries, where);
  detail::walk(s, actions, settings, visitor);
  if (queries.empty() || environment == nullptr) return;
  environment->respond(queries);
  // Later modules first so that a change of parameter count does not move earlier offsets.
  for (std::size_t k = queries.size(); k-- > 0;) s.set_parameters(where[k], queries[k].parameters);
}

}  // namespace fspm::lsystem
