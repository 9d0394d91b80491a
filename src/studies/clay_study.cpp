#include "studies/clay_study.hpp"

namespace iwb::studies {

namespace {

std::vector<FigureSpec> clay_figures() {
  const std::vector<std::pair<std::string, std::string>> cv{{"cv100_hcc", "HCC 100 kPa"},
                                                            {"cv100_hce", "HCE 100 kPa"},
                                                            {"cv300_hcc", "HCC 300 kPa"},
                                                            {"cv300_hce", "HCE 300 kPa"}};
  const std::vector<std::pair<std::string, std::string>> cnl{{"cnl100_hcc", "HCC 100 kPa"},
                                                             {"cnl100_hce", "HCE 100 kPa"},
                                                             {"cnl300_hcc", "HCC 300 kPa"},
                                                             {"cnl300_hce", "HCE 300 kPa"}};
  const std::vector<std::pair<std::string, std::string>> cns{
      {"cnl100_hcc", "HCC CNL"},
      {"cns100_K100_hcc", "HCC K = 100 kPa"},
      {"cns100_K1000_hcc", "HCC K = 1000 kPa"},
      {"cnl100_hce", "HCE CNL"},
      {"cns100_K100_hce", "HCE K = 100 kPa"},
      {"cns100_K1000_hce", "HCE K = 1000 kPa"}};
  return {
      {"fig_6_3a_cv_tau", "CV: shear stress (seed Fig. 6.3a)", Axis::kGamma, Axis::kTau, cv},
      {"fig_6_3b_cv_sigma_n", "CV: normal stress (seed Fig. 6.3b)", Axis::kGamma, Axis::kSigmaN,
       cv},
      {"fig_6_4_cv_path", "CV: stress path (seed Fig. 6.4)", Axis::kSigmaN, Axis::kTau, cv},
      {"fig_6_5a_cnl_tau", "CNL: shear stress (seed Fig. 6.5a)", Axis::kGamma, Axis::kTau, cnl},
      {"fig_6_5b_cnl_eps_n", "CNL: normal strain (seed Fig. 6.5b)", Axis::kGamma, Axis::kEpsN, cnl},
      {"fig_6_6a_cns_tau", "CNS from 100 kPa: shear stress (seed Fig. 6.6)", Axis::kGamma,
       Axis::kTau, cns},
      {"fig_6_6b_cns_sigma_n", "CNS from 100 kPa: normal stress (seed Fig. 6.6)", Axis::kGamma,
       Axis::kSigmaN, cns},
      {"fig_6_7a_roughness",
       "CNL 100 kPa, kappa_r 1, 0.75, 0.5, each model's own scheme (seed Fig. 6.7a)",
       Axis::kGamma,
       Axis::kTau,
       {{"cnl100_hcc", "HCC 1"},
        {"cnl100_hcc_k0.75", "HCC 0.75"},
        {"cnl100_hcc_k0.5", "HCC 0.5"},
        {"cnl100_hce", "HCE 1"},
        {"cnl100_hce_k0.75", "HCE 0.75"},
        {"cnl100_hce_k0.5", "HCE 0.5"}}},
      {"fig_6_7b_schemes",
       "kappa_r 0.5: Arnold & Herle against Stutz & Masin, small strains (seed Fig. 6.7b)",
       Axis::kGamma,
       Axis::kTau,
       {{"cnl100_hcc_k0.5", "HCC Arnold & Herle"},
        {"cnl100_hcc_k0.5_stutz-masin", "HCC Stutz & Masin"},
        {"cnl100_hce_k0.5_arnold-herle", "HCE Arnold & Herle"},
        {"cnl100_hce_k0.5", "HCE Stutz & Masin"}},
       0.02},
      {"fig_6_11a_cyclic_cnl",
       "HCE without and with intergranular strain, cyclic CNL 100 kPa, Table 6.4 (seed Fig. 6.11)",
       Axis::kGamma,
       Axis::kTau,
       {{"cyclic_cnl_hce", "HCE"}, {"cyclic_cnl_hce-igs", "HCE with intergranular strain"}}},
      {"fig_6_11b_cyclic_cv",
       "HCE without and with intergranular strain, cyclic CV from 100 kPa: stress path",
       Axis::kSigmaN,
       Axis::kTau,
       {{"cyclic_cv_hce", "HCE"}, {"cyclic_cv_hce-igs", "HCE with intergranular strain"}}},
  };
}

}  // namespace

StudyDefinition clay_study() {
  return {"clay",
          "iwb clay study: the interface models of seed 6.4",
          "Seed section 6.4 redrawn: Table 6.1 (lambda* 0.1, kappa* 0.01, nu 0.2, phi_c 25 deg, N "
          "1.0) and Table 6.4 for "
          "the intergranular strain; normally consolidated starts (OCR 1) at K0 = 1 - sin phi_c, "
          "d_s = 1 mm.",
          clay_cases(),
          clay_claims,
          clay_figures()};
}

}  // namespace iwb::studies
