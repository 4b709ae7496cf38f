/* rfir: the meanings of rfir-sim's INI keys (config_ini/sim_*.ini,
 * docs/simulator.md). */
#include "ini_key_docs_tables.h"

namespace rfir::common::detail {
namespace {
const std::vector<TKeyRow> kSim = {
    // [simulation]
    {"simulation", "dt", "s",
     "simulation step: odometry and every sensor are sampled at it (unless event "
     "driven)"},
    {"simulation", "start_time", "s", "clock of the first step"},
    {"simulation", "max_duration", "s", "cut the run there (0: the whole trajectory)"},
    {"simulation", "area", "m",
     "min_x min_y max_x max_y of the tag carpet, emitter lattice and landmarks"},
    // [robot]
    {"robot", "reader_ring_radius", "m",
     "radius of the default ring of 8 RFID readers under the robot"},
    {"robot", "reader_half_size", "m", "half side of the default readers' square"},
    {"robot", "readers", "m",
     "explicit reader layout 'x y [half_x half_y], ...' in the robot frame (IDs R0, "
     "R1, ...), instead of the ring"},
    {"robot", "receivers", "m",
     "IR receivers 'x y z, ...' in the robot frame (IDs IR0, IR1, ...)"},
    // [trajectory]
    {"trajectory", "type", "-",
     "path: loop (the inset rectangle), predefined (shape 1..5), random (waypoints) or "
     "lawnmower (coverage stripes)"},
    {"trajectory", "predefined", "-",
     "predefined shape: 1 rectangle, 2 serpentine, 3 L, 4 diamond, 5 bow tie"},
    {"trajectory", "rotation", "-",
     "heading: none (constant), follow (turn in place to face each leg) or spin "
     "(rotate at spin_rate while translating)"},
    {"trajectory", "laps", "laps", "times the loop, shape or lawnmower path is driven"},
    {"trajectory", "waypoints", "waypoints", "waypoints of a random path"},
    {"trajectory", "stripe_spacing", "m",
     "distance between the stripes of a lawnmower path"},
    {"trajectory", "margin", "m", "the path stays this far inside the area"},
    {"trajectory", "speed", "m/s", "the robot's constant speed along the legs"},
    {"trajectory", "turn_rate", "rad/s", "turn rate of rotation = follow"},
    {"trajectory", "spin_rate", "rad/s", "turn rate of rotation = spin"},
    {"trajectory", "start_phi_deg", "deg",
     "initial heading (follow starts facing its first leg)"},
    {"trajectory", "spots", "spots",
     "stops spread evenly along the path (written to NAME.spots.tum; 0: none)"},
    {"trajectory", "spot_pause", "s", "time the robot stands at each spot"},
    // [kidnap]
    {"kidnap", "enabled", "-", "lift and carry the robot once during the run"},
    {"kidnap", "time", "s", "time from the start when the robot is lifted"},
    {"kidnap", "carry_time", "s",
     "how long it is carried (no reads, no observations meanwhile)"},
    {"kidnap", "to_time", "s",
     "put it down at the pose it had at this earlier time, replaying its path from "
     "there"},
    {"kidnap", "to_pose", "m, m, deg",
     "or put it down at 'x y phi_deg'; the rest of its path moves rigidly with it"},
    {"kidnap", "odometry", "-",
     "odometry while carried: frozen (records go on with an unchanged pose) or stop "
     "(no records)"},
    // [odometry]
    {"odometry", "k_xy", "m/sqrt(m)", "position random walk of the odometry noise"},
    {"odometry", "k_phi_rot", "rad/sqrt(rad)", "heading random walk per radian turned"},
    {"odometry", "k_phi_xy", "rad/sqrt(m)", "heading random walk per metre travelled"},
    {"odometry", "scale_sigma", "share",
     "std of the per-run translation scale error (wheel radius)"},
    {"odometry", "rot_scale_sigma", "share",
     "std of the per-run rotation scale error (wheel base)"},
    {"odometry", "heading_drift_sigma", "rad/m", "std of the per-run heading drift"},
    {"odometry", "scale_error", "share",
     "fixed translation scale error added to the drawn one (a known miscalibration)"},
    {"odometry", "rot_scale_error", "share",
     "fixed rotation scale error added to the drawn one"},
    {"odometry", "heading_drift_error", "rad/m",
     "fixed heading drift added to the drawn one"},
    {"odometry", "rate", "Hz",
     "odometry records per second, out of step with the sensors (0: one per dt step)"},
    {"odometry", "latency", "s",
     "a record at t reports the wheels' pose at t minus this"},
    {"odometry", "slip_times", "s",
     "times from the start of wheel slips, 't, ...' (the true path is unchanged)"},
    {"odometry", "slip_count", "slips", "further slips at uniform random times"},
    {"odometry", "slip_size", "m",
     "extra travel a slip adds to its odometry interval (negative: less travel)"},
    {"odometry", "slip_heading_deg", "deg", "extra turn a slip adds"},
    // [rfid]
    {"rfid", "enabled", "-", "simulate the floor's RFID tags and the robot's readers"},
    {"rfid", "density", "tags/m^2",
     "tags per square metre, on a square grid centred in the area"},
    {"rfid", "placement_sigma", "m", "std of each tag's displacement from the grid"},
    {"rfid", "miss_probability", "probability",
     "a read inside a reader's square is dropped"},
    {"rfid", "uid_prefix", "-", "prefix of the tag IDs, followed by 8 random hex digits"},
    {"rfid", "ghost_rate", "per poll",
     "probability that a poll also reports a real tag the reader did not read"},
    {"rfid", "ghost_distance", "m",
     "'min max' distance of a ghost-read tag from the reader's centre"},
    {"rfid", "dead_readers", "-, s, s",
     "'reader from to, ...': the reader (index) reads nothing in [from, to) s from the "
     "start"},
    {"rfid", "empty_polls", "-",
     "write: a poll that read nothing is written (negative information); omit: it is "
     "not"},
    {"rfid", "polling", "-",
     "together: every reader at every step; round_robin: one reader per poll"},
    {"rfid", "poll_rate", "Hz", "round_robin: polls per second of each reader"},
    {"rfid", "poll_jitter", "s", "round_robin: uniform jitter of each poll time"},
    // [ir]
    {"ir", "enabled", "-", "simulate the ceiling IR emitters and the robot's receivers"},
    {"ir", "pitch", "m", "spacing of the repeated-ID emitter lattice"},
    {"ir", "ceiling_height", "m", "emitters' height above the floor"},
    {"ir", "height_spread", "m", "each emitter's height moved by a uniform +- this"},
    {"ir", "reference_height", "m",
     "vertical receiver-emitter distance at which the voltage curve holds (the "
     "voltage scales with its inverse square)"},
    {"ir", "repeated_codes", "-",
     "codes of the repeated-ID emitters, tiled over the lattice"},
    {"ir", "unique_codes_per_id", "codes", "codes combined into one unique ID"},
    {"ir", "with_repeated", "-", "the lattice has repeated-ID emitters"},
    {"ir", "with_unique", "-",
     "the lattice has a unique-ID emitter in the centre of every four"},
    {"ir", "all_unique", "-", "unique IDs at every lattice position"},
    {"ir", "visible_radius", "m",
     "horizontal distance within which a receiver sees an emitter"},
    {"ir", "volt_sigma", "V", "std of the receiver voltage noise"},
    {"ir", "period", "s", "time between IR readings"},
    {"ir", "output", "-",
     "decoded: codes and voltage; raw: the sampled receiver window (decoded by the "
     "FFT decoder)"},
    {"ir", "rate_hz", "Hz", "raw output: sampling rate of a window"},
    {"ir", "samples", "samples", "raw output: samples per window"},
    {"ir", "raw_noise_sigma", "V", "raw output: noise std per sample"},
    {"ir", "raw_offset", "V", "raw output: the window's constant offset"},
    {"ir", "failed", "-",
     "failed emitters (in the map, never emitting): an ID (every emitter with it) or "
     "'x y' (the one there), comma-separated"},
    {"ir", "moved", "m",
     "'x y dx dy, ...': the emitter at (x, y) is written at (x + dx, y + dy) in "
     "NAME.map.txt (a map error)"},
    {"ir", "wrong_code_rate", "probability", "a reading in view has wrong codes"},
    {"ir", "wrong_code_other_id", "share",
     "share of the wrong codes that spell another emitter's ID"},
    {"ir", "volt_outlier_rate", "probability",
     "a reading's voltage is replaced by a uniform one in [0, volt_outlier_max]"},
    {"ir", "volt_outlier_max", "V", "upper end of the outlier voltages"},
    // [range_bearing]
    {"range_bearing", "enabled", "-",
     "simulate point landmarks and a range-and-bearing sensor"},
    {"range_bearing", "density", "landmarks/m^2", "landmarks per square metre, uniform"},
    {"range_bearing", "sensor_pose", "m, m, deg",
     "'x y yaw_deg' of the sensor on the robot"},
    {"range_bearing", "max_range", "m", "the sensor measures landmarks up to this range"},
    {"range_bearing", "fov_deg", "deg", "field of view, centred on the sensor's axis"},
    {"range_bearing", "sigma_range", "m", "range noise std"},
    {"range_bearing", "sigma_bearing_deg", "deg", "bearing noise std"},
};
}  // namespace

const std::vector<TKeyRow>& simKeyRows() {
    return kSim;
}
}  // namespace rfir::common::detail
