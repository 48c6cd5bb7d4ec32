// fspm.developmental_model: developmental stages of a static tree (Pirk chapter 5).
#include <pybind11/stl.h>

#include <string>
#include "python/bindings.hpp"

#include "stages/developmental_model.hpp"

namespace fspm::python {

void bind_stages(py::module_& m) {
  using stages::DevelopmentalModel;
  py::class_<DevelopmentalModel>(
      m, "DevelopmentalModel",
      "Developmental stages of a static tree (Pirk 2013, ch. 5; docs/stages.md): any stage t in "
      "[0, 1] between a seedling (t = 0, empty) and the given tree (t = 1), computed directly")
      .def(
          "stage",
          [](const DevelopmentalModel& model, double t) {
            TreeGraph out;
            model.stage(t, out);
            return out;
          },
          py::arg("t"),
          "The stage at time t in [0, 1] (clamped) as a Tree: the edges grown by then, a growing "
          "edge at its partial length (m); order is the Gravelius level - 1 and birth_time the "
          "time in [0, 1] at which the edge starts growing")
      .def_property_readonly("chain_count", &DevelopmentalModel::chain_count,
                             "Number of chains (runs of edges of one Gravelius level), >= 1")
      .def_property_readonly("added_branch_count", &DevelopmentalModel::added_branch_count,
                             "Branches added below the crown (Pirk 5.3.5), 0 unless added=True")
      .def_property_readonly("overlap_branch_count", &DevelopmentalModel::overlap_branch_count,
                             "Of the added branches, those in the overlap region above the crown "
                             "base (Pirk 5.3.5), 0 unless added_overlap=True")
      .def_property_readonly("shed_branch_count", &DevelopmentalModel::shed_branch_count,
                             "Branches shed before the given tree read back from its radii, 0 "
                             "unless shed_branches=True")
      .def_property_readonly(
          "crown_ratio",
          [](const DevelopmentalModel& model) { return model.crown().crown_ratio(); },
          "Crown ratio of the given tree: crown length / height (Pirk Table 5.1)")
      .def_property_readonly(
          "levels",
          [](const DevelopmentalModel& model) {
            const auto& l = model.level();
            return std::vector<int>(l.begin(), l.end());
          },
          "Gravelius level per node of the given tree (1 on the main axis), a list of int")
      .def_property_readonly(
          "start_times", [](const DevelopmentalModel& model) { return model.start_time(); },
          "Time in [0, 1] at which each node of the given tree starts growing, a list of float");

  m.def(
      "developmental_model",
      [](const TreeGraph& tree, bool thickest_continues, bool added, double added_gamma,
         bool added_overlap, const std::vector<std::pair<NodeId, double>>& age_branches,
         const std::vector<std::pair<NodeId, NodeId>>& copy_branches, bool shed_branches,
         const std::string& growth_profiles) {
        stages::StagesParams p;
        p.continuation = thickest_continues ? stages::Continuation::kThickest
                                            : stages::Continuation::kLeastDeviation;
        p.added.enabled = added || added_overlap;
        p.added.gamma = added_gamma;
        p.added.overlap = added_overlap;
        for (const auto& [node, delta] : age_branches) p.edits.age.push_back({node, delta});
        for (const auto& [from, to] : copy_branches) p.edits.copy.push_back({from, to});
        p.shed.enabled = shed_branches;
        p.profiles = stages::profile_choice_from_name(growth_profiles);
        return DevelopmentalModel(tree, p);
      },
      py::arg("tree"), py::arg("thickest_continues") = true, py::arg("added") = false,
      py::arg("added_gamma") = 1.0, py::arg("added_overlap") = false,
      py::arg("age_branches") = std::vector<std::pair<NodeId, double>>{},
      py::arg("copy_branches") = std::vector<std::pair<NodeId, NodeId>>{},
      py::arg("shed_branches") = false, py::arg("growth_profiles") = "constant",
      "Analyse a Tree into a DevelopmentalModel (chains, growth rates, angles, radii). "
      "thickest_continues=False uses Pirk's rule (the child deviating least continues the axis); "
      "added=True adds the branches a young tree had below the crown and sheds them as the crown "
      "ratio of Pirk eq. 5.10 (exponent added_gamma) falls; added_overlap=True (implies added) "
      "also "
      "fills the overlap region above the crown base where stratified clipping finds more tissue "
      "than main-axis cutting (Pirk 5.3.5). Growth-based editing (Pirk 5.4.1): age_branches, a "
      "list of (node, dt), makes the branch holding internode `node` older by dt (units of t; "
      "negative: younger), so that it shows at each stage what it would show dt later; "
      "copy_branches, a list of (from, to), copies the branch holding internode `from` rigidly "
      "to the end of internode `to`, growing from the time the tree reaches `to` at the age the "
      "source had when it started; shed_branches=True stands a shed branch wherever a radius "
      "holds more pipes than its children need (pipe model, Shinozaki et al. 1964), grown as "
      "the lateral of the closest pipes and shed when complete; growth_profiles is 'constant' "
      "(Pirk eq. 5.3), 'by_chain', 'logistic' or 'accelerating'; raises ValueError for an empty "
      "tree or bad parameters");

  m.def("seasonal_time", &stages::seasonal_time, py::arg("t"), py::arg("years"), py::arg("c") = 1.2,
        py::arg("s") = 0.0,
        "Pirk eq. 5.11: t in [0, 1] remapped over `years` (>= 1) seasons; c in [1, 1.4] is the "
        "dormancy strength (1: growth stops once a year), s the shift (0 growth, 0.5 angles)");
}

}  // namespace fspm::python
