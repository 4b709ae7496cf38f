/* rfir: the meanings of rfir-localize's INI keys (config_ini/ir_localize.ini,
 * docs/ir.md). */
#include "ini_key_docs_tables.h"

namespace rfir::common::detail {
namespace {
constexpr const char* kLik = "MetricMap_irEmitterMap_*_likelihoodOpts";

const std::vector<TKeyRow> kLocalize = {
    // [localization]
    {"localization", "num_particles", "particles",
     "robot particles M; too few fail to settle when the first unique ID comes late "
     "(docs/results_ir.md)"},
    {"localization", "init_area", "m",
     "'x0 y0 x1 y1': the initial particles are uniform over this box and every heading"},
    {"localization", "init_margin", "m",
     "without init_area, the emitters' bounding box grown by this"},
    {"localization", "start_from_reading", "-",
     "at the first unique-ID reading draw every particle from the poses that explain it "
     "(false: weigh the uniform prior with it, as the thesis)"},
    {"localization", "start_history", "m",
     "with start_from_reading, also weigh those particles by the repeated-ID readings "
     "of this much odometry path before it (0: off)"},
    {"localization", "start_pose", "-",
     "unknown: global localization from the first unique ID; log: start where the "
     "log's header says (e.g. a dock)"},
    {"localization", "start_std_xy", "m", "start_pose = log: position spread about it"},
    {"localization", "start_std_phi", "rad", "start_pose = log: heading spread about it"},
    {"localization", "sensor_resetting", "-",
     "redraw particles from a unique-ID reading that too few particles explain"},
    {"localization", "reset_min_fraction", "share",
     "reset when less than this share of the particles (by weight) would see the "
     "unique-ID emitter that is read"},
    {"localization", "reset_ratio", "share", "share of the particles redrawn at a reset"},
    {"localization", "reset_distance_sigma", "m",
     "distance jitter of the redrawn particles"},
    {"localization", "reset_view_margin", "m",
     "for resetting, 'in view' means within the visible radius plus this, so that a "
     "good track at the edge of view is not reset"},
    {"localization", "repeated_before_unique", "-",
     "use repeated-ID readings before the first unique one (association = particle "
     "only)"},
    {"localization", "association_max_std", "m",
     "association = estimate: attribute repeated IDs against the estimate only while the "
     "particles' largest position std is below this (0: always)"},
    {"localization", "ess_threshold", "share of M",
     "resample when the effective sample size falls below this share"},
    {"localization", "resampling", "-", "resampling scheme of the robot particles"},
    {"localization", "decode_raw", "-",
     "FFT-decode raw receiver windows that carry no codes"},
    {"localization", "gate_max_std", "m",
     "the particles count as settled below this position spread, which turns on the "
     "gating, lost-track and emitter checks (0: all off)"},
    {"localization", "gate_loglik", "log-likelihood",
     "a reading is consistent when enough predicted particles give it a log-likelihood "
     "above this"},
    {"localization", "gate_min_fraction", "share",
     "a reading that less than this share of the predicted particles (by weight) "
     "explain is an outlier and not used"},
    {"localization", "lost_min_readings", "readings",
     "inconsistent readings each of lost_min_ids unique IDs must give before the track "
     "counts as lost and is redrawn"},
    {"localization", "lost_min_ids", "IDs",
     "unique IDs that must disagree for a lost track"},
    {"localization", "emitter_check_radius", "m",
     "while settled, an emitter this close to a receiver is expected to answer"},
    {"localization", "emitter_min_checks", "checks",
     "checks before an emitter's health (failed, inconsistent) is judged"},
    {"localization", "inconsistent_weight", "-",
     "factor on the log-likelihood of the readings of an emitter judged inconsistent "
     "(moved, a map error)"},
    // [motion]
    {"motion", "k_xy", "m/sqrt(m)", "the filter's odometry position random walk"},
    {"motion", "k_phi_rot", "rad/sqrt(rad)",
     "the filter's heading random walk per radian turned"},
    {"motion", "k_phi_xy", "rad/sqrt(m)",
     "the filter's heading random walk per metre travelled"},
    {"motion", "scale_sigma", "share", "std of the odometry translation scale error"},
    {"motion", "rot_scale_sigma", "share", "std of the odometry rotation scale error"},
    {"motion", "heading_drift", "rad/m", "std of the odometry heading drift"},
    {"motion", "min_std_xy", "m", "position noise std added to every step"},
    {"motion", "min_std_phi", "rad", "heading noise std added to every step"},
    // The emitter map, created by MRPT's map factory.
    {"MetricMap", "irEmitterMap_count", "maps", "emitter maps (one)"},
    {"MetricMap_irEmitterMap_*_creationOpts", "emitter_file", "-",
     "emitter file (emitter <id> <x> <y> <z>), relative to the INI's folder; empty: "
     "--emitters"},
    {"MetricMap_irEmitterMap_*_insertOpts", "enableObservationInsertion", "-",
     "MRPT's map option: the map takes observations (the emitter map ignores them)"},
    {"MetricMap_irEmitterMap_*_insertOpts", "enableObservationLikelihood", "-",
     "MRPT's map option: the map weighs particles with IR readings"},
    {"MetricMap_irEmitterMap_*_insertOpts", "enableSaveAs3DObject", "-",
     "MRPT's map option: the map appears in 3D scenes"},
    {kLik, "curve_c0", "V",
     "voltage curve V = c2 d^2 + c1 d + c0 at fit_height: constant term"},
    {kLik, "curve_c1", "V/m", "voltage curve: linear term"},
    {kLik, "curve_c2", "V/m^2", "voltage curve: quadratic term"},
    {kLik, "fit_height", "m",
     "vertical receiver-emitter distance the curve was fitted at"},
    {kLik, "max_distance", "m",
     "horizontal distance the curve was fitted up to (visible radius)"},
    {kLik, "height_model", "-",
     "fixed: the curve at any height; inverse_square: scaled by (fit_height / h)^2; "
     "angular: same off-axis angle, scaled by the inverse square"},
    {kLik, "vertical_distance", "m",
     "h for the height model (0: emitter z minus receiver z)"},
    {kLik, "sigma_volts", "V", "voltage noise std of a reading"},
    {kLik, "sigma_belief", "m",
     "std of the belief (eq. 5.1) that picks which emitter of a repeated ID was read"},
    {kLik, "volt_outlier_weight", "share",
     "weight of a uniform voltage mixed into the likelihood, so one wild voltage costs "
     "little (0: off)"},
    {kLik, "volt_outlier_range", "V", "the outlier voltages' range [0, this]"},
    {kLik, "out_of_range_loglik", "log-likelihood",
     "added when a particle puts the receiver beyond the emitter's visible radius"},
    {kLik, "out_of_range_ramp", "m",
     "the out-of-range term ramps in linearly over this distance past the visible "
     "radius, so that a track a centimetre off at the edge is kept"},
    {kLik, "miss_loglik", "log-likelihood",
     "added when a receiver that saw nothing would be near an emitter (0: off; harmful "
     "with failed emitters in the map)"},
    {kLik, "miss_radius_fraction", "share",
     "'near': within this share of the visible radius"},
    {kLik, "area_margin", "m",
     "out_of_area_loglik applies beyond this distance outside the emitters' box"},
    {kLik, "out_of_area_loglik", "log-likelihood",
     "added when the robot would be outside the emitters' box (0: off)"},
    {kLik, "association", "-",
     "estimate: IDs attributed against the robot estimate (the thesis); particle: each "
     "particle takes its own most likely emitter"},
};
}  // namespace

const std::vector<TKeyRow>& localizeKeyRows() {
    return kLocalize;
}
}  // namespace rfir::common::detail
