#include "lsystem/query_pass.hpp"

#include "lsystem/turtle_core.hpp"

namespace fspm::lsystem {
namespace {

bool is_query(detail::Action a) {
  return a == detail::Action::kQueryP || a == detail::Action::kQueryH ||
         a == detail::Action::kQueryU || a == detail::Action::kQueryL ||
         a == detail::Action::kCommunicate;
}

// Records the turtle frame at every query module of the walked string, in string order.
class QueryVisitor {
 public:
  void forward(const Eigen::Vector3d&, const Eigen::Vector3d&, double, detail::Frame&) {}
  void polygon_begin(const detail::Frame&) {}
  void vertex(const Eigen::Vector3d&) {}
  void polygon_end(const detail::Frame&) {}
  void surface(double, const detail::Frame&) {}
  void sphere(double, bool, const detail::Frame&) {}
  void query(std::size_t, detail::Action, const detail::Frame& f) { frames.push_back(f); }
  std::vector<detail::Frame> frames;
};

}  // namespace

void fill_query_modules(const LSystem& system, ModuleString& s, const TurtleSettings& settings,
                        OpenEnvironment* environment, const ModuleString* drawn) {
  const auto actions = detail::action_table(system.symbols);
  std::vector<std::size_t> where;  // query modules of s, in order
  for (std::size_t i = 0; i < s.size(); ++i) {
    if (is_query(actions[s.symbol(i)])) where.push_back(i);
  }
  if (where.empty()) return;
  QueryVisitor visitor;
  if (drawn != nullptr) detail::walk(*drawn, actions, settings, visitor);
  // The drawn string must hold the same query modules in the same order; otherwise (a
  // homomorphism that adds or removes them) the derived string itself is walked.
  if (drawn == nullptr || visitor.frames.size() != where.size()) {
    visitor.frames.clear();
    detail::walk(s, actions, settings, visitor);
  }
  std::vector<EnvironmentQuery> queries;
  std::vector<std::size_t> comm;
  for (std::size_t k = 0; k < where.size(); ++k) {
    const std::size_t i = where[k];
    const detail::Frame& f = visitor.frames[k];
    const detail::Action a = actions[s.symbol(i)];
    if (a == detail::Action::kCommunicate) {
      EnvironmentQuery q;
      q.position = f.position;
      q.heading = f.heading;
      q.left = f.left;
      q.up = f.up;
      const auto p = s.parameters(i);
      q.parameters.assign(p.begin(), p.end());
      queries.push_back(std::move(q));
      comm.push_back(i);
      continue;
    }
    const Eigen::Vector3d& v = a == detail::Action::kQueryP   ? f.position
                               : a == detail::Action::kQueryH ? f.heading
                               : a == detail::Action::kQueryU ? f.up
                                                              : f.left;
    auto p = s.parameters(i);
    for (std::size_t c = 0; c < p.size() && c < 3; ++c) p[c] = v[static_cast<int>(c)];
  }
  if (queries.empty() || environment == nullptr) return;
  environment->respond(queries);
  // Later modules first so that a change of parameter count does not move earlier offsets.
  for (std::size_t k = queries.size(); k-- > 0;) s.set_parameters(comm[k], queries[k].parameters);
}

}  // namespace fspm::lsystem
