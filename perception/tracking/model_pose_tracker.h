#pragma once
// The pose tracker that needs no markers: each part's mesh and its pose in one frame (an
// operator's placement or a pose estimator's) are enough. Every part is followed from frame to
// frame by region-based tracking (region_pose.h) against colour models it learns as it goes;
// parts hide each other's contour lines where the current estimates put them in front (and the
// furniture hides them where it stands in front), and a
// part whose silhouette no longer stands out (a hand over it, out of the picture) keeps its last
// pose, reported invalid, and is looked for around it in the next frames (a grid of shifts
// across the view scored by contrast, the best tracked from; then among the places on the
// furniture where it could have been put down, standing as before or laid on a side,
// support_search.h, judged on its visible lines; lost for longer, also where its colours show
// anywhere in the frame, color_blobs.h).
// A part found so is followed back into the frames it was missed in. A part seen in the last
// two frames is predicted to go on as it moved (a carry). Parts are tracked nearest first; a
// resting part that is not measured while another moves is held at its rest (not searched for)
// and reported there only if that is borne out (ModelTrackerOptions::hold_resting); one that
// parts resting beside it rode away from is looked for where the same ride would have taken it
// (ModelTrackerOptions::ride_prediction). A rest's turn about the vertical, which its outline
// shows weakly, is reported as the part's print shows it once the rest is over
// (ModelTrackerOptions::rest_turn).
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <opencv2/core.hpp>

#include "perception/markers/marker_scene.h"
#include "perception/render/part_meshes.h"
#include "perception/render/rasterizer.h"
#include "perception/render/render_mesh.h"
#include "perception/tracking/color_histograms.h"
#include "perception/tracking/contour_model.h"
#include "perception/tracking/pose_tracker.h"
#include "perception/tracking/region_pose.h"
#include "perception/tracking/ride_prediction.h"
#include "perception/tracking/support_search.h"
#include "perception/tracking/surface_flow.h"
#include "perception/tracking/tracker_init.h"

namespace demoplan::perception {

struct PrintShot;  // appearance_error.h

struct ModelPart {
  std::string id;
  bool planning = true;
  RenderMesh mesh;  // part frame, metres
};

struct ModelTrackerOptions {
  ContourModelOptions contour;
  std::string contour_cache;  // folder keeping the contour models between runs; "": none
  RegionTrackingOptions region;
  SurfaceFlowOptions flow;
  // A part counts as seen in a frame when its contrast (region_pose.h) reaches both bars and
  // enough of its contour's lines find an edge; only then does its pose move.
  double lost_contrast = 0.08;
  double relative_contrast = 0.7;    // of the part's running mean contrast
  double lost_used_fraction = 0.3;   // of the contour's lines
  double learn_contrast = 0.85;      // of the running mean: the colour models learn from the frame
  double reference_rate = 0.1;       // of the running mean
  // A part not seen is looked for across the view up to this many of its radii from its last
  // pose (candidates scored by contrast; the best `search_tries` tracked from).
  double search_radii = 2.5;
  int search_tries = 3;
  double search_contrast = 0.9;   // of the running mean: a part found by the search
  double search_used_fraction = 0.5;  // of its lines finding an edge: a part found by the search
  // A part lost while not carried (seen moving in fewer than three frames in a row before) and
  // tracked on from its last pose to farther than this many of its radii from it, is taken only
  // on a find's evidence (search_contrast, search_used_fraction): shelf_1 with the occluder, the
  // mustard lost at its rest as the hand passed was pulled 100 mm onto the cracker box's edge at
  // contrast 0.60 against a bar of 0.59, and reported there for 30 frames.
  double stale_jump_radii = 0.5;
  // Found within its radius of where it was seen in the last frame, a tracked frame's contrast
  // is enough when this fraction of its lines find an edge (> 1: never).
  double near_used_fraction = 0.85;
  // A part still not found is looked for where it could have come to rest (a carried part is
  // put down, often half behind the furniture, and the search at its last depth misses it):
  // standing on one of the furniture's supports as at its last rest, turned about the vertical
  // (support_search.h), its centre's image within `rest_search_radii` of its radii of where it
  // was last seen; candidates scored by their contrast over the lines left visible, the best
  // `rest_search_tries` tracked from (at the support's depth).
  bool rest_search = true;
  double rest_search_radii = 3.0;
  // The longer it has been lost, the farther it may have been carried before it was put down
  // (shelf_1 with the occluder: hidden at the start of the carry, put down 3.3 radii from where
  // it was last seen): not found within that reach, it is looked for beyond it, out to
  // `rest_search_growth` radii more a frame lost after the first `rest_search_growth_after`, up
  // to `rest_search_max_radii`; taken there only in full view (at most a tenth of its lines
  // hidden, nine tenths finding an edge, standing out as much as `search_contrast` asks).
  double rest_search_growth = 0.05;
  int rest_search_growth_after = 0;
  double rest_search_max_radii = 6.0;
  int rest_search_turns = 12;           // over the whole turn, one of them the last seen turn
  // Not found as it stood: looked for laid on each side of its box (a box put down on its side),
  // within rest_search_radii, half as many turns each; taken only in full view, as beyond the reach.
  bool rest_search_faces = true;
  // A box turned half round about the vertical shows the same outline: a find is turned so when
  // the part's print, drawn there, differs from the frame by less than this fraction of what it
  // differs as found (appearance_error.h; 0: never).
  double rest_search_half_turn_ratio = 0.8;
  double rest_search_density = 4.0;     // grid points per radius
  int rest_search_climbs = 12;          // best candidates moved and turned while they stand out more
  int rest_search_tries = 4;            // of those, tracked from
  int rest_search_every = 2;            // frames, while it stays lost (and in the frame after a find)
  // Judged on the lines the furniture and the other parts leave visible, not on all of them (a
  // part half hidden shows half its lines): enough of it shows, most of its visible lines find
  // an edge, it stands out enough, it still rests on the support once tracked (within the
  // height and tilt), and it is found at the same place as in the frame before (found or seen
  // there: at rest, as a part held above a support does not stay put). Candidates whose core
  // would be inside a furniture box (a wall) are not tried; of those that pass, the one with
  // the most evidence (edges found times contrast) is taken.
  double rest_visible_fraction = 0.3;   // of its lines visible
  double rest_used_fraction = 0.75;     // of the visible lines finding an edge
  double rest_contrast = 0.6;           // of the running mean: lower than search_contrast, as
                                        // where it was put down may lie on another background
  double rest_height_tolerance = 0.01;  // m above or into the support
  double rest_tilt_deg = 10.0;          // of its up axis from the last rest's
  // or from the last rest's stood level (standing_level): a rest tracked some degrees off level
  // (on a carried tray) does not refuse the part found standing level.
  bool rest_tilt_from_level = true;
  double rest_confirm_mm = 10.0;        // between the two frames' finds
  // A part tracked to a rest that stands on nothing (tilted, floating, sunk: its depth off along
  // its line of sight, which a silhouette gives weakly; waiter_0's sugar box 17 cm deep, tilted
  // 18 degrees, on the tray; standing on another part counts as standing) is looked for where it
  // could stand level, on the furniture and on the carriers' tops, within `rest_recheck_across`
  // of its radius of where it shows; the find is taken when it stands out at most
  // `rest_recheck_margin` less than the rest does (the rest's own colours favour the rest).
  bool rest_recheck = true;
  // A rest that floats (its lowest point more than `rest_recheck_unplaced_height` above the highest
  // level under it, or over none) and is found standing nowhere near in
  // `rest_recheck_unplaced_checks` rechecks in a row is no rest: the tracker followed something
  // still that is not the part (ur5_workbench without markers: the bracket, carried behind the
  // hand, tracked onto something still 12 cm above the table, hiding the flanged cylinder behind
  // it). Its samples since it began are taken back, the part is lost there, and it is looked for
  // only where it could stand (the rest searches) until seen: not tracked or searched from that
  // pose. (The benchmark's own rests float up to 5 cm: waiter_0's cracker box over the tray.)
  bool rest_recheck_unplaced = true;
  double rest_recheck_unplaced_height = 0.08;  // m
  int rest_recheck_unplaced_checks = 2;
  int rest_recheck_every = 6;           // frames, while it rests on nothing
  double rest_recheck_height = 0.02;    // m: its lowest point from a level it stands on
  double rest_recheck_margin = 0.05;    // of contrast
  double rest_recheck_across = 0.25;    // of its radius: the find's centre from the rest's, in the image
  // A part lost for `global_search_after` frames and not found within the rest search's reach is
  // looked for where its colours show in the frame (color_blobs.h: blobs beyond the plain reach
  // at least `global_blob_fraction` as large as it showed when last seen, the
  // `global_search_blobs` most like it, in colour and size), standing as at its last rest or laid on a side, within
  // `global_search_radii` of its radii of each blob's centre. Taken only in full view, standing
  // out as a find beyond the reach must, or at least `rest_contrast` when its print agrees with
  // the frame there (appearance_error.h: at most `global_print_outliers` of its pixels differing
  // by more than start_cover_difference): waiter_0 with the occluder, the cracker box put down on
  // another face stands out 0.61 against its running mean's 0.69, its print within 2 of 255.
  bool global_search = true;
  int global_search_after = 4;
  int global_search_every = 6;  // frames, while it stays lost (and in the frame after a find)
  double global_blob_fraction = 0.1;
  int global_search_blobs = 4;
  double global_search_radii = 0.5;
  double global_print_outliers = 0.05;
  // A part found at rest after a gap is followed back into the gap through the last frames
  // (kept while a part is not seen), as long as it is seen there: the end of the carry it was
  // lost in (its last approach, hidden from the search while it still moved) dates the release.
  int follow_back_frames = 15;
  // A part come to rest (its centre still over three frames) may have been there before its
  // estimate got there (a hand setting it down drags the outline along as it withdraws): each
  // of up to `date_rests_back_frames` frames before those three that shows it at its rest, as a
  // tracked frame does and within the rest hold when tracked from there, is reported at the rest,
  // latest first, until one does not. (The last frames are then kept all the time.)
  bool date_rests_back = true;
  int date_rests_back_frames = 8;
  // Also a frame in which, tracked from the rest, it moves (a hand withdrawing over it pulls the
  // outline), when the rest stands out there at least as much as the pose reported then.
  bool date_rests_back_by_contrast = true;
  double prediction = 0.8;        // of the last frame's motion across the view, carried on
  double rest_px = 1.0;           // a part whose centre's image moved less over 3 frames holds its depth
  double rest_hold_px = 2.0;      // a resting part's smaller moves (and turns) are not taken
  double rest_hold_deg = 2.0;
  double rest_hidden_fraction = 0.4;  // of its lines hidden: a resting part is not measured
  // A part lost while it moved (carried behind the hand) still passes in front of the resting
  // parts its last pose overlapped, for this many frames: the hand may be setting it down there.
  int lost_mover_frames = 10;
  // A resting part not measured while another part moves (the one hand busy with that one) is
  // held at its rest, not looked for elsewhere, from a frame it was measured at rest in; those
  // frames are reported at the rest, with this confidence (an inference: the event detector's
  // lowest, 0.5), once the hold is borne out: by its next measurement at the rest, or by the
  // parts that moved meanwhile all seen at rest again. Otherwise none of them is.
  bool hold_resting = true;
  double held_confidence = 0.5;
  // A hold borne out while the part was never measured at its rest: its colours are learnt
  // anew from the held frames in which nothing modelled covered it.
  bool hold_relearn = true;
  // Two parts that moved during a hold the same way (each farther than hold_ride_min, their
  // moves apart by less than this fraction of the longer) rode on something: the held part may
  // have ridden with them, and the hold is not borne out by their rest.
  double hold_ride_min = 0.05;  // m
  double hold_ride_tolerance = 0.3;
  // A part not measured at its rest (held there, or lost from there) while at least two parts
  // left their rests together (within `ride_start_frames` of each other) and moved as one rigid
  // body (each farther than hold_ride_min; the best rigid motion in the horizontal plane leaves
  // at most `ride_tolerance` plus `ride_tolerance_fraction` of the longest move), one of them
  // from beside it (the same support: its lowest point within `ride_height` of the part's, or
  // its centre within `ride_radii` of the part's radii), rode with them on a tray or a board
  // that is no furniture (ride_prediction.h): it is looked for at its rest moved by that motion
  // in every frame it is not measured, until it is seen at rest or they part, and taken there
  // when seen as in a tracked frame with half its lines finding an edge; found there after the
  // ride (its riders at rest), it rests there at once.
  bool ride_prediction = true;
  double ride_height = 0.03;  // m
  double ride_radii = 4.0;
  int ride_start_frames = 3;
  double ride_tolerance = 0.03;  // m
  double ride_tolerance_fraction = 0.1;
  double light_tolerance = 0.05;      // a frame whose light drifted further is brought back (light_correction.h)
  // On the start frame: the part segmented around its start (GrabCut), and the start refined on
  // that segmentation until it stays (at most this many rounds at its depth, as many free).
  int settle_grabcut_iterations = 4;
  // A part whose print (appearance_error.h) differs from the start frame by more than
  // `start_cover_difference` (0-255, mean over the channels) in more than
  // `start_covered_fraction` of the pixels it shows in, once settled, is not what the frame
  // shows there: something not modelled is over it (the demonstrator's hand: waiter_0, its
  // track pulled 39 mm onto the forearm), or its start is off. The operator is warned.
  double start_cover_difference = 20.0;
  double start_covered_fraction = 0.1;
  int settle_rounds = 10;
  double settle_visible_fraction = 0.7;  // of its silhouette: a start less visible is kept as it is
  double settle_contrast_gain = 0.03;  // a settled start is taken when it stands out this much more
  double settle_depth_contrast_gain = 0.1;  // and moved in depth, this much more
  // A rest's turn about the vertical shows weakly in its outline (a box seen near a face's normal
  // changes its outline little as it turns), and strongly in its print: once the rest is over
  // (or the video), its samples are turned about the vertical through the part's centre while
  // its print (appearance_error.h) differs less from the clearest frame of that rest (the fewest
  // pixels differing by more than start_cover_difference, looked at every `rest_turn_every`
  // frames it is measured at rest, until one has at most `rest_turn_clear` of them; a rest whose
  // clearest frame has more than `rest_turn_covered` is left as it is: something not modelled, a
  // hand, over it), when that lowers the difference to `rest_turn_ratio` of what it was, by at
  // most `rest_turn_max_deg`. The tracking itself goes on from its own poses: only the reported
  // samples turn.
  bool rest_turn = true;
  int rest_turn_every = 6;
  double rest_turn_clear = 0.02;
  double rest_turn_covered = 0.05;
  double rest_turn_ratio = 0.95;
  double rest_turn_max_deg = 11.5;
  // A placement (the start, or the operator's placing a part again) is looked at every
  // `rest_turn_every` frames until the track has taken the part farther than its radius from
  // it (placement_witness.h): its print there clear (at most `rest_turn_covered` of the pixels
  // differing) in a frame where the tracked pose's differs by `witness_margin` more, the samples
  // from the placement to the last frame it was clear in (and on while the track stays where it
  // was then) are reported at the placement, turned as a rest is.
  bool witness_placements = true;
  double witness_margin = 0.05;
  // Threads scoring a lost part's candidate poses (0: one per core); the tracks are the same
  // whatever the number.
  int search_threads = 0;
};

class ModelPoseTracker final : public PoseTracker {
public:
  // `furniture`: what may hide the parts (its contour lines there are left out). Throws
  // InputError when `init` lacks a part's pose (naming the part) or corrects a part it does not
  // track; start() throws it when a start or a correction puts a part behind the camera or its
  // centre outside the image.
  ModelPoseTracker(std::vector<ModelPart> parts, TrackerInit init, std::string init_source,
                   std::vector<FurnitureMesh> furniture = {}, const ModelTrackerOptions& options = {});
  ~ModelPoseTracker() override;

  std::string name() const override { return "model"; }
  const std::vector<TrackedPart>& parts() const override { return parts_; }
  void start(const TrackingStart& start) override;
  std::vector<PoseObservation> track(int frame, const cv::Mat& image) override;
  PoseTracks finish() override;
  std::vector<std::string> warnings() const override { return warnings_; }

private:
  struct State;
  // The furniture and the parts at their estimates; without part `skip` (>= 0), as where to look
  // for a lost part its stale pose hides nothing.
  OcclusionMap occlusion_map(int skip = -1) const;
  // Moves part k's start to where the start frame shows it (an operator's placement is a few
  // millimetres to centimetres off).
  void settle_start(const cv::Mat& image, size_t k);
  // At the occlusion map's scale, holding the furniture's depth once it is drawn (else cleared).
  Rasterizer occlusion_rasterizer() const;
  // work(i) for every i in [0, count), `chunk` at a time on the search threads (each i must
  // write only its own result).
  void on_search_threads(size_t count, size_t chunk, const std::function<void(size_t)>& work) const;
  // Where the centre of part k's model shows in the image at that pose, relative to the
  // principal point (only differences and distances of these are used).
  Eigen::Vector2d centre_in_image(size_t k, const Pose& camera_T_part) const;
  // The radius of part k's bounding sphere in the image at that pose (pixels, at its centre's depth).
  double radius_in_image(size_t k, const Pose& camera_T_part) const;
  // Whether a moving part, nearer the camera, overlaps part k's image (bounding circles).
  // (`lost_moving`: parts lost in their carry a few frames ago, lost_mover_frames, count too.)
  bool passed_in_front(size_t k, const std::vector<bool>& moving, const std::vector<bool>& lost_moving) const;
  // Part k looked for around its last pose: the best of the tracked candidates.
  RegionFrameResult search(const cv::Mat& image, int k, const OcclusionMap& map) const;
  // Whether a measurement shows its part: it stands out at least `bar` (the part's contrast bar)
  // with lost_used_fraction of its lines finding an edge.
  bool seen_in(const RegionFrameResult& r, double bar) const;
  // Whether a measurement of resting part k lies within what its rest holds to (its centre's
  // image within rest_hold_px of the last, its turn within rest_hold_deg): no move.
  bool within_rest_hold(size_t k, const Pose& measured) const;
  // Part k looked for where it could have come to rest on the furniture (rest_search options);
  // the best candidate that passes the rules that judge it on its visible lines, if any
  // (`where_colours_show` set when it was found by global_search).
  std::optional<RegionFrameResult> rest_search(const cv::Mat& image, int k, bool* where_colours_show = nullptr) const;
  // Where the rest search looks: within `radii` of the part's radii (at least `min_reach_px`)
  // of where it was last seen (`beyond`: only outside the plain reach, on stricter evidence); on
  // the faces other than its last rest's (`other_faces`: rest_search_faces, on the same strict
  // evidence); on `levels` (none: the furniture's); `stood_level` from its last rest's
  // orientation rather than as that was (a rest that stands on nothing: recheck_rests); around
  // each of `around` (image pixels) rather than where it was last seen (where its colours show:
  // global_search, on the strict evidence, or a lower contrast with its print borne out).
  struct RestSearchArea {
    double radii = 3.0;
    double min_reach_px = 60.0;
    bool beyond = false, other_faces = false, stood_level = false;
    const std::vector<SupportLevel>* levels = nullptr;
    const std::vector<Eigen::Vector2d>* around = nullptr;
  };
  // `map`: what the furniture and the other parts hide (occlusion_map(k)).
  std::optional<RegionFrameResult> rest_search(const cv::Mat& image, int k, const OcclusionMap& map,
                                               const RestSearchArea& area) const;
  // Parts measured at rest in `frame` standing on no support (the furniture's, a carrier's or
  // another part's top): looked for where they could stand (rest_recheck); a find that shows
  // them as well is where the whole rest was.
  void recheck_rests(int frame, const cv::Mat& image, const std::vector<bool>& resting);
  // Part k's rest since rest_began, found standing nowhere, taken back: lost there (rest_recheck_unplaced).
  void lose_rest(size_t k, int frame);
  // A find of the rest search, or the same turned half round about the vertical when the part's
  // print says so (rest_search_half_turn_ratio).
  RegionFrameResult by_print(const cv::Mat& image, int k, const OcclusionMap& map, const RegionFrameResult& found) const;
  // A part not measured at its rest since the last frame, while parts that rested beside it
  // left together as one body, may have ridden with them: its ride is noted; a ride whose
  // riders went apart no longer tells where it is, and is dropped.
  void watch_rides(int frame, const std::vector<bool>& resting);
  // Each part as a ride's detection sees it in `frame` (ride_prediction.h): tracked when measured in it or the last.
  std::vector<RidePart> ride_parts(int frame) const;
  RideRules ride_rules() const;
  // The operator's corrections for `frame` (TrackerInit::corrections): each part placed again is
  // taken from there as from a start, at rest, its colours learnt there too. Returns the parts.
  std::vector<size_t> apply_corrections(int frame, const cv::Mat& image);
  // Part k's index among the models, or -1.
  int part_index(const std::string& id) const;
  // Part k, found at rest in `frame`, tracked back from there through the kept frames before it
  // while it is seen (contrast `bar`), filling its samples there.
  void follow_back(size_t k, int frame, double bar);
  // Part k, placed again in `frame` on another part that moved while k was lost (a tray): it rode
  // it. Its unseen frames before are where that part took it, and its last rest before them,
  // measured off along its line of sight only, where the ride began.
  void ride_back(size_t k, int frame);
  // The clearest frame of each part's current rest, and that rest turned by its print once over.
  void watch_rest_turns(int frame, const cv::Mat& image, const OcclusionMap& map, const std::vector<bool>& resting);
  void turn_rest(size_t k);
  // Part k at `shot`'s pose turned about the vertical by its print in that frame (world), when
  // the print differs at most rest_turn_ratio as much after, by at most rest_turn_max_deg.
  std::optional<Pose> turned_by_print(size_t k, const PrintShot& shot) const;
  // Each placement against its track (ModelTrackerOptions::witness_placements), and the
  // placement's rest reported once part k's witness closes.
  void watch_placements(int frame, const cv::Mat& image);
  void close_witness(size_t k);
  // Part k, come to rest in `frame`: the kept frames before its `seen_for` still ones (three;
  // one for a part placed again) reported at the rest while they show it there (date_rests_back).
  // Returns the earliest frame it is now reported at the rest in.
  int date_rest_back(size_t k, int frame, double bar, int seen_for = 3);

  std::vector<ModelPart> models_;
  std::vector<FurnitureMesh> furniture_;
  TrackerInit init_;
  std::string init_source_;  // the start file, for messages
  ModelTrackerOptions options_;
  std::vector<TrackedPart> parts_;
  std::vector<std::unique_ptr<ContourModel>> contours_;  // built on the first start()
  std::unique_ptr<State> state_;
  std::vector<std::string> warnings_;
};

// The tracker for the parts of a marker scene (its markers, if any, are not used): their meshes
// and the furniture from the task or cell the scene names (part_meshes.h), in `data_dir`.
std::unique_ptr<ModelPoseTracker> make_model_tracker(const MarkerScene& scene, const std::string& scene_file,
                                                     const std::string& data_dir, TrackerInit init,
                                                     std::string init_source, const ModelTrackerOptions& options = {});

}  // namespace demoplan::perception
