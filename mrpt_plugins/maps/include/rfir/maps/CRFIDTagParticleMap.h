/* rfir: map of RFID tags (and range-bearing landmarks), one independent
 * particle filter or fixed-lag particle smoother per tag (PF-SLAM / PS-SLAM,
 * SPEC sections 4, 5, 7). See docs/tag-maps.md. */
#pragma once

#include <rfir/models/detection_likelihood.h>
#include <rfir/models/range_bearing.h>
#include <rfir/models/tag_estimator.h>

#include <mrpt/config/CLoadableOptions.h>
#include <mrpt/maps/CMetricMap.h>
#include <mrpt/poses/CPose2D.h>
#include <mrpt/random/RandomGenerators.h>

#include <cstdint>
#include <exception>
#include <string>
#include <unordered_map>
#include <vector>

namespace rfir::obs {
class CObservationRFIDReaders;
}

namespace rfir::maps {
/** How re-reads of a tag weigh the robot (see docs/tag-maps.md). */
enum class TRobotUpdatePolicy {
    /** INI "literal": the papers' Algorithm 1: update the tag first, then weigh
     * the robot with the updated estimate, on every read (incl. the first). */
    Literal,
    /** INI "revisit": only the first read of a new visit (the tag was absent
     * from at least `revisit_min_gap` RFID observations since its last read)
     * weighs the robot, against the estimate from before this visit; the tag
     * is updated after. Reads within a visit (and of the first pass) do not. */
    Revisit,
    /** INI "revisit_all": every read of a new visit weighs the robot, against
     * the estimate frozen at the visit's start; reads of the first pass do not. */
    RevisitAll
};

/** Which robot pose places the reader when a tag is created or re-weighed. */
enum class TTagRobotPose {
    /** INI "mean": the robot's mean pose (the papers). */
    Mean,
    /** INI "samples_init": a new tag's particle l = a uniform point of the
     * reader placed by a robot pose drawn from the robot's particle set
     * (marginalises the robot pose at creation); re-reads use the mean. */
    SamplesInit,
    /** INI "samples": also re-reads: tag particle l is weighed against the
     * reader placed by a freshly drawn robot pose. */
    Samples,
    /** INI "samples_visit": the reads of a tag's first visit share the robot's
     * error, so they are placed by the robot mean (as the papers do), and the tag
     * keeps, per particle, a robot pose drawn from the robot set at its first
     * read; its estimate is the particles moved as if the robot had been at
     * those poses (tag = drawn robot pose + position relative to the robot),
     * and the move is made permanent when the second visit starts. */
    SamplesVisit
};

/** What a robot particle is weighed against (see docs/tag-maps.md). */
enum class TRobotLikelihood {
    /** INI "tag_mean": the tag's mean estimate (the papers). */
    TagMean,
    /** INI "tag_particles": the detection likelihood averaged over K tag
     * particles (a fixed evenly spaced subset), so an uncertain tag weighs
     * the robot less sharply than a well-known one. */
    TagParticles
};

class CRFIDTagParticleMap : public mrpt::maps::CMetricMap {
    DEFINE_SERIALIZABLE(CRFIDTagParticleMap, rfir::maps)

  public:
    /** One mapped tag or landmark. */
    struct TTagEntry {
        std::string id;
        rfir::models::CTagEstimatorPtr estimator;  //!< per [tagmap] estimator
        rfir::models::PointEstimate estimate;      //!< cached from the estimator
        /** Estimate frozen at the start of the current visit (RevisitAll). */
        rfir::models::PointEstimate visitStartEstimate;
        /** K tag particles for the robot likelihood (TagParticles), refreshed
         * at every update, and the subset frozen at the visit's start. */
        std::vector<mrpt::math::TPoint2D> sample, visitStartSample;
        /** SamplesVisit, during the first visit: robot poses drawn at the first
         * read (one per particle) and the robot mean they are relative to. */
        std::vector<mrpt::math::TPose2D> spreadPoses;
        mrpt::math::TPose2D spreadOrigin{0, 0, 0};
        double spreadTravel = 0;  //!< RFID track travel (m) at the first read
        uint64_t detections = 0;  //!< number of (reader, tag) reads
        /** Of these, reads the tag's estimate at the time contradicted
         * (DetectionLikelihood::contradicts, or the estimate more than
         * contradict_margin outside the reader's square; map.txt's last
         * column). */
        uint64_t contradicted = 0;
        /** Reads that agreed with it since it was (last) placed, the reads
         * in a row that contradicted it since, and how often it was placed
         * again (reseat_contradicted). */
        uint64_t support = 0, againstRun = 0, reseats = 0;
        uint64_t visits = 0;        //!< number of visits (first pass = 1)
        uint64_t lastReadStep = 0;  //!< index (1-based) of the last observation read in
        double lastReadTravel = 0;  //!< robot path length (m) at that observation
        std::vector<mrpt::math::TPoint2D> particles() const {
            return estimator->particles();
        }
        /** Bytes this entry owns (estimator and containers, by capacity). */
        size_t memoryBytes() const;
    };

    CRFIDTagParticleMap();

    /** @name Access to the estimates (O(1) by ID; the list ones are O(N)).
     * @{ */
    const TTagEntry* getTag(const std::string& id) const;
    const TTagEntry* getLandmark(const std::string& id) const;
    size_t tagCount() const { return m_tags.size(); }
    size_t landmarkCount() const { return m_landmarks.size(); }
    /** Bytes the tag and landmark tables own: entries, estimators, hash nodes
     * and buckets (counted by capacity; allocator headers not included). */
    size_t memoryBytes() const;
    /** All tags / landmarks, sorted by ID (for output; O(N log N)). */
    std::vector<const TTagEntry*> tags() const;
    std::vector<const TTagEntry*> landmarks() const;
    /** @} */

    /** True if the robot filter must insert an observation (update the tags)
     * BEFORE weighing its particles with computeObservationLikelihood (policy
     * Literal); false if it must weigh first, then insert (Revisit*). */
    bool updateTagsBeforeWeighing() const;
    /** True if only a visit's first read weighs the robot (Revisit). */
    bool weighsOnlyFirstReads() const;

    /** Names for CObservationBearingRange landmark IDs (index = ID), as in the
     * log header; IDs without a name use their decimal text. */
    void setLandmarkNames(const std::vector<std::string>& names) {
        m_landmarkNames = names;
    }
    const std::vector<std::string>& landmarkNames() const { return m_landmarkNames; }
    std::string landmarkName(int32_t id) const;

    /** True if `o` reads a tag the map does not hold. */
    bool readsNewTags(const rfir::obs::CObservationRFIDReaders& o) const;
    /** Inserts only the reads of tags the map does not hold (placed as
     * insertObservation places them, with the whole observation's reader
     * geometry); known tags are neither updated nor weighed by the readers
     * that missed them. For a pose the known tags disagree with (the kidnap
     * check's open run, [kidnap] map_new_tags_in_run). Does nothing and
     * returns false if `o` reads no new tag. */
    bool insertNewTags(const rfir::obs::CObservationRFIDReaders& o,
                       const mrpt::poses::CPose2D& robot);

    /** Would a read of this tag in the next observation start a new visit?
     * (false for unknown tags). */
    bool isNewVisit(const std::string& tagId) const;

    /** The reads of one observation that weigh the robot (per robot_update
     * policy), resolved against the map once per update: weighing M particles
     * then costs only the likelihoods, not an ID lookup per particle and read.
     * Valid while the map is not modified. */
    struct TRobotReads {
        struct TRead {
            const rfir::models::PointEstimate* est = nullptr;
            const std::vector<mrpt::math::TPoint2D>* sample = nullptr;  //!< RFID
            rfir::models::ReaderArea area;                              //!< RFID
            double range = 0, yaw = 0;                                  //!< range-bearing
            const std::string* id = nullptr;  //!< tag or landmark ID (the map's)
            /** RFID, robot_negative_information: the large readers of the
             * observation near `area` that did not read the tag (on the
             * tag's first weighing read of the observation only). */
            std::vector<rfir::models::ReaderArea> missedBy;
        };
        bool rangeBearing = false;
        double sensorX = 0, sensorY = 0, sensorYaw = 0;  //!< range-bearing
        rfir::models::DetectionLikelihood det;
        std::vector<TRead> reads;
    };
    /** Resolves `obs` (RFID or bearing-range; false for other kinds). */
    bool resolveRobotReads(const mrpt::obs::CObservation& obs, TRobotReads& out) const;
    /** The same sum as computeObservationLikelihood(obs, robot) for the
     * resolved reads. `baseSum` (optional) receives the sum of the same terms
     * without the outlier mixture, which the kidnap check reads (docs/slam.md,
     * "Kidnapping"). */
    double robotReadsLogLikelihood(const TRobotReads& r, const mrpt::math::TPose2D& robot,
                                   double* baseSum = nullptr) const;
    /** The same with c, s = cos, sin of robot.phi (cached by the caller). */
    double robotReadsLogLikelihood(const TRobotReads& r, const mrpt::math::TPose2D& robot,
                                   double c, double s, double* baseSum) const;

    /** Moves one tag's (or landmark's) estimate rigidly by (dx, dy) m: every
     * stored state, the visit-start estimate and sample (the engine's
     * correction of tags correlated with the robot, docs/slam.md "Tags that
     * move with the robot"). False if the ID is not mapped. */
    bool translateEntry(const std::string& id, bool landmark, double dx, double dy);

    /** @name Instrumentation: tag entries touched (created or updated).
     * @{ */
    size_t lastInsertTouched() const { return m_lastTouched; }
    uint64_t totalTouched() const { return m_totalTouched; }
    /** @} */

    /** Writes `tag <id> <x> <y> <sx> <sy>` and `landmark ...` lines (textlog.md
     * output format), sorted by ID. Throws on I/O error. */
    void saveToTextFile(const std::string& path) const;

    /** Adds fixed tags and landmarks from a map text file (`tag <id> <x> <y>
     * [<sx> <sy>]`, `landmark ...`, as textlog.md; other records skipped), e.g.
     * a ground truth to localize against: each entry's particles are drawn
     * from N(x, sx^2) x N(y, sy^2) (all at (x, y) without deviations). Throws
     * naming the file and line of a malformed record. INI:
     * `<map>_creationOpts` key `prior_map_file`. */
    void loadPriorFromTextFile(const std::string& path);

    /** Base seed of the per-update generators (every insert reseeds from
     * (seed, step), so copies made by serialization continue identically). */
    void setRandomSeed(uint64_t seed) { insertionOptions.seed = seed; }

    /** Robot poses drawn from the robot's particle set (in proportion to the
     * weights), used by the next inserts when `tag_robot_pose` is not `mean`;
     * empty = the insert pose. Not serialized (an input of the next insert). */
    void setRobotSamples(std::vector<mrpt::math::TPose2D> poses) {
        m_robotSamples = std::move(poses);
    }
    bool usesRobotSamples() const {
        return insertionOptions.tagRobotPose != TTagRobotPose::Mean;
    }

    // CMetricMap interface
    bool isEmpty() const override;
    void saveMetricMapRepresentationToFile(
        const std::string& filNamePrefix) const override;
    void getVisualizationInto(mrpt::opengl::CSetOfObjects& outObj) const override;
    std::string asString() const override;

    struct TInsertionOptions : public mrpt::config::CLoadableOptions {
        /** estimator: a registered name (rfir::models::tagEstimatorNames()). */
        std::string estimator = rfir::models::kParticleFilterName;
        /** Each tag's estimator as the models define it: num_particles (L),
         * lag, smoother_step_sigma (m), resampling, ess_threshold and
         * roughening_sigma (m) (the last two PF only). */
        rfir::models::TTagEstimatorParams params;
        uint64_t seed = 1;                                 //!< seed
        TTagRobotPose tagRobotPose = TTagRobotPose::Mean;  //!< tag_robot_pose
        /** reseat_contradicted: a tag that more reads in a row contradict
         * than agreed with it since it was placed is placed again. */
        bool reseatContradicted = true;
        /** contradict_margin (m): a read also contradicts a tag whose
         * estimate lies this far outside the read's reader square (negative:
         * only the outlier floor's test). The floor's test scales with the
         * reader: with 300 mm readers it calls a tag 0.5 m off consistent. */
        double contradictMargin = 0.1;
        /** hold_outvoted: a read that contradicts a tag while the tag's
         * support still outweighs the contradicting run does not update it
         * (one ghost read does not drag a tag). */
        bool holdOutvoted = true;
        /** negative_information (p_d in [0, 0.99]; 0: off, the papers; the
         * stock slam INIs: 0.5): after each RFID observation, a tag on its
         * first visit, read in the last negative_window observations, whose
         * estimate lies near a polled reader (half-sizes >=
         * negative_min_half_size) that did not read it is weighed by
         * 1 - p_d x the step model's likelihood of a read: a tag that a
         * large square did not read is not in it. */
        double negativeInformation = 0;
        uint64_t negativeWindow = 30;      //!< negative_window (observations)
        double negativeMinHalfSize = 0.1;  //!< negative_min_half_size (m)
        /** spread_commit_travel (m): samples_visit makes the spread permanent
         * at the first new visit after this much robot path since the tag's
         * first read (0: the second visit, which with a ring of readers can be
         * the same pass, the tag crossing from one reader to the next). */
        double spreadCommitTravel = 0;

        void loadFromConfigFile(const mrpt::config::CConfigFileBase& source,
                                const std::string& section) override;
        void dumpToTextStream(std::ostream& out) const override;
    } insertionOptions;

    struct TLikelihoodOptions : public mrpt::config::CLoadableOptions {
        /** detection_model, beta, gaussian_sigma_scale: weigh both tag and robot
         * particles (the papers use one function for both). */
        rfir::models::DetectionModelParams detection;
        /** rb_sigma_range (m), rb_sigma_bearing_deg (INI in degrees). */
        rfir::models::RangeBearingParams rangeBearing;
        TRobotUpdatePolicy robotUpdate = TRobotUpdatePolicy::Literal;  //!< robot_update
        size_t revisitMinGap = 1;  //!< revisit_min_gap (observations without the tag)
        /** revisit_min_travel (m): a new visit also needs this much robot path
         * since the tag's last read (0 = off); ties the reads of one pass under
         * several readers into one visit. */
        double revisitMinTravel = 0;
        /** rb_use_landmark_cov: add the landmark estimate's covariance to the
         * range-bearing noise when weighing the robot (false = the papers). */
        bool rbUseLandmarkCov = false;
        /** robot_likelihood, robot_likelihood_k (K tag particles, RFID only). */
        TRobotLikelihood robotLikelihood = TRobotLikelihood::TagMean;
        size_t robotLikelihoodK = 12;
        /** robot_negative_information (p_d in [0, 0.99]; 0: off, the papers):
         * a read that weighs the robot brings the polls of the same
         * observation that missed the tag, by the large readers ([tagmap]
         * negative_min_half_size) near the one that read it: each weighs
         * the robot particle by 1 - p_d P(read) (miss_model.h), at the tag
         * estimate the read weighs against. */
        double robotNegativeInformation = 0;
        static constexpr size_t kMaxRobotLikelihoodK = 64;  //!< its INI bound

        void loadFromConfigFile(const mrpt::config::CConfigFileBase& source,
                                const std::string& section) override;
        void dumpToTextStream(std::ostream& out) const override;
    } likelihoodOptions;

    MAP_DEFINITION_START(CRFIDTagParticleMap)
    std::string priorMapFile;  //!< creationOpts prior_map_file ("": none)
    rfir::maps::CRFIDTagParticleMap::TInsertionOptions insertionOpts;
    rfir::maps::CRFIDTagParticleMap::TLikelihoodOptions likelihoodOpts;
    /** A refused INI value, raised when the map is created (see
     * loadFromConfigFile_map_specific). */
    std::exception_ptr loadError;
    MAP_DEFINITION_END(CRFIDTagParticleMap)

  protected:
    void internal_clear() override;
    bool internal_insertObservation(const mrpt::obs::CObservation& obs,
                                    const std::optional<const mrpt::poses::CPose3D>&
                                        robotPose = std::nullopt) override;
    double internal_computeObservationLikelihood(
        const mrpt::obs::CObservation& obs,
        const mrpt::poses::CPose3D& takenFrom) const override;
    bool internal_canComputeObservationLikelihood(
        const mrpt::obs::CObservation& obs) const override;

  private:
    using TTable = std::unordered_map<std::string, TTagEntry>;
    TTable m_tags, m_landmarks;
    std::vector<std::string> m_landmarkNames;
    std::vector<mrpt::math::TPose2D> m_robotSamples;
    /** Per sensor (0 = RFID, 1 = range-bearing): observations inserted, robot
     * path length over them (straight segments between insert poses), and the
     * last insert pose. Visits are counted on these. */
    struct TSensorTrack {
        uint64_t steps = 0;
        double travel = 0;
        bool hasPose = false;
        double lastX = 0, lastY = 0;
    };
    TSensorTrack m_track[2];
    /** RFID track's travel at the last negative_information update (m). */
    double m_notReadTravel = -1;
    size_t m_lastTouched = 0;
    uint64_t m_totalTouched = 0;

    friend struct CRFIDTagParticleMapImpl;
};

/** Registers the library's classes with MRPT (also done at load time; calling
 * it keeps the library linked under --as-needed). Idempotent. */
void registerAllClasses();

}  // namespace rfir::maps
