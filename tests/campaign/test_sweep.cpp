// Campaign expansion without an engine: the cartesian product, each job's scene, names, the
// refusal of a bad value before anything runs, the reuse rule and the Slurm array.
#include <catch2/catch.hpp>
#include <cstdlib>
#include <filesystem>

#include "campaign/job_start.hpp"
#include "campaign/jobs.hpp"
#include "campaign/slurm.hpp"
#include "campaign/sweep.hpp"
#include "common/errors.hpp"
#include "dem/scene/scene.hpp"
#include "io/toml_reader.hpp"
#include "support/sweep_fixtures.hpp"

using namespace iwb;
namespace fs = std::filesystem;

namespace {
std::vector<std::string> names(const std::vector<campaign::Job>& jobs) {
  std::vector<std::string> out;
  for (const auto& j : jobs) out.push_back(j.name);
  return out;
}
const campaign::Job& job_named(const std::vector<campaign::Job>& jobs, const std::string& name) {
  for (const auto& j : jobs)
    if (j.name == name) return j;
  FAIL("no job " << name);
  return jobs.front();
}
}  // namespace

TEST_CASE("sweep: the jobs are the cartesian product of the axes, named by their values",
          "[campaign]") {
  const auto jobs = campaign::expand_jobs(campaign::load_sweep("data/sweeps/example.toml"));
  REQUIRE(jobs.size() == 2 * 3 * 2);
  CHECK(names(jobs) == std::vector<std::string>{
                           "rn0.25_cnl_s1", "rn0.25_cnl_s2", "rn0.25_cns-50_s1", "rn0.25_cns-50_s2",
                           "rn0.25_cv_s1", "rn0.25_cv_s2", "rn0.5_cnl_s1", "rn0.5_cnl_s2",
                           "rn0.5_cns-50_s1", "rn0.5_cns-50_s2", "rn0.5_cv_s1", "rn0.5_cv_s2"});
  for (const auto& j : jobs) CHECK(j.engine == "liggghts");
}

TEST_CASE("sweep: a job's scene is the base with its values set in their own tables",
          "[campaign]") {
  const auto jobs = campaign::expand_jobs(campaign::load_sweep("data/sweeps/example.toml"));
  const auto& job = job_named(jobs, "rn0.25_cns-50_s2");
  const auto scene = dem::parse_scene(job.scene_text, "job.toml");
  const double d50 = scene.particles.d50_m;
  CHECK(scene.wall.height_m == Approx(0.25 * d50));
  CHECK(scene.plate.height_m == Approx(1.0 * d50));  // [plate] height_d50 is another key
  CHECK(scene.boundary.kind == driver::BoundaryKind::kCNS);
  CHECK(scene.boundary.K_Pa_per_m == Approx(50e3 / 1e-3));
  CHECK(scene.seed == 2);
  CHECK(scene.particle_count == 400);         // untouched keys keep the base's values
  CHECK(job.scene_text.rfind("# ", 0) == 0);  // a header says where the text came from
  const auto cv = dem::parse_scene(job_named(jobs, "rn0.5_cv_s1").scene_text, "cv.toml");
  CHECK(cv.boundary.kind == driver::BoundaryKind::kCV);
  CHECK(cv.wall.height_m == Approx(0.5 * d50));
}

TEST_CASE("sweep: a value that sets a wall's profile replaces the base's whole [wall] table",
          "[campaign]") {
  // The truth scene's wall is a sawtooth (pitch and height); a flat wall refuses both keys, so a
  // key-by-key merge would make the flat job an invalid scene.
  const auto jobs = campaign::expand_jobs(campaign::load_sweep("data/sweeps/truth2_rn.toml"));
  const auto flat = dem::parse_scene(job_named(jobs, "flat_s1_cnl").scene_text, "job.toml");
  CHECK(flat.wall.kind == dem::ProfileKind::kFlat);
  const auto rough =
      dem::parse_scene(job_named(jobs, "sawtooth-2-0.1_s1_cnl").scene_text, "job.toml");
  CHECK(rough.wall.height_m == Approx(0.1 * rough.particles.d50_m));
  CHECK(rough.plate.height_m == Approx(1.5 * rough.particles.d50_m));  // the plate keeps its table
}

TEST_CASE("sweep: [set] keys apply to every job", "[campaign]") {
  const auto jobs = campaign::expand_jobs(campaign::load_sweep("data/sweeps/tiny.toml"));
  REQUIRE(names(jobs) == std::vector<std::string>{"u0.05", "u10", "u0.1"});  // 10.0 reads as 10
  const std::vector<double> travel_mm = {0.05, 10.0, 0.1};
  for (std::size_t i = 0; i < jobs.size(); ++i) {
    const auto scene = dem::parse_scene(jobs[i].scene_text, "tiny.toml");
    CHECK(scene.particle_count == 180);
    CHECK(scene.shear.inertial_number == Approx(1e-2));
    CHECK(scene.shear.displacement_m == Approx(travel_mm[i] * 1e-3));
  }
}

TEST_CASE("sweep: a value the scene refuses stops the whole sweep, naming the job, key and value",
          "[campaign]") {
  const auto dir = test::campaign_dir("refused");
  // 5 d50 does not divide the 12 d50 box: the second job is invalid, so none may run
  const auto file = test::write_sweep(dir, "[[axis]]\nkey = \"wall.pitch_d50\"\nvalues = [2, 5]\n");
  CHECK_THROWS_MATCHES(campaign::run_sweep(test::sweep_options(file, dir / "out")), InputError,
                       Catch::Matchers::Predicate<InputError>([](const InputError& e) {
                         const std::string m = e.what();
                         return m.find("job pitch_d50-5 (wall.pitch_d50 = 5)") !=
                                    std::string::npos &&
                                m.find("does not divide the box length") != std::string::npos &&
                                m.find("nothing was run") != std::string::npos;
                       }));
  CHECK_FALSE(fs::exists(dir / "out"));  // not even the scenes are written
  const auto typo = test::write_sweep(dir, "[[axis]]\nkey = \"wall.hieght_d50\"\nvalues = [0.5]\n");
  CHECK_THROWS_WITH(campaign::expand_jobs(campaign::load_sweep(typo)),
                    Catch::Contains("hieght_d50"));
  const auto not_a_table = test::write_sweep(dir, "[[axis]]\nkey = \"seed.value\"\nvalues = [1]\n");
  CHECK_THROWS_WITH(campaign::expand_jobs(campaign::load_sweep(not_a_table)),
                    Catch::Contains("'seed' is a value, not a table"));
}

TEST_CASE("sweep: unknown engines, missing files and colliding names are refused", "[campaign]") {
  const auto dir = test::campaign_dir("refused_file");
  CHECK_THROWS_WITH(campaign::load_sweep(test::write_sweep(dir, "engines = [\"lammps\"]\n")),
                    Catch::Contains("lammps") && Catch::Contains("liggghts"));
  CHECK_THROWS_WITH(
      campaign::load_sweep(test::write_sweep(dir, "[compare]\nparams = \"nope.toml\"\n")),
      Catch::Contains("compare.params") && Catch::Contains("no such file"));
  const auto twins =
      test::write_sweep(dir,
                        "[[axis]]\nkey = \"seed\"\nvalues = [1, 2]\nlabel = \"x\"\n"
                        "[[axis]]\nkey = \"specimen.particles\"\nvalues = [400]\nlabel = \"\"\n"
                        "[[axis]]\nkey = \"description\"\nvalues = [\"a b\", \"a-b\"]\n");
  CHECK_THROWS_WITH(campaign::expand_jobs(campaign::load_sweep(twins)),
                    Catch::Contains("two jobs would be named"));
  CHECK_THROWS_WITH(
      campaign::load_sweep(test::write_sweep(dir, "[[axis]]\nkey = \"seed\"\nvalues = []\n")),
      Catch::Contains("non-empty list"));
}

TEST_CASE(
    "sweep: a complete run of the same scene is reused, a stopped one resumed, another scene "
    "redone",
    "[campaign]") {
  const auto dir = test::campaign_dir("job_start");
  using campaign::JobStart;
  CHECK(campaign::how_to_start(dir / "none", "abc") == JobStart::kFresh);
  const auto manifest = [&](const std::string& status, const std::string& sha) {
    io::write_manifest(dir, {{"status", status}, {"scene", {{"sha256", sha}}}});
  };
  manifest("complete", "abc");
  CHECK(campaign::how_to_start(dir, "abc") == JobStart::kSkip);
  CHECK(campaign::how_to_start(dir, "other") == JobStart::kFresh);
  manifest("interrupted at stage shear", "abc");
  CHECK(campaign::how_to_start(dir, "abc") == JobStart::kResume);
  manifest("failed: servo did not converge (stage consolidate)", "abc");
  CHECK(campaign::how_to_start(dir, "abc") == JobStart::kResume);
  manifest("running", "abc");  // killed hard: its finished stages are still good
  CHECK(campaign::how_to_start(dir, "abc") == JobStart::kResume);
}

TEST_CASE("sweep --emit slurm: a job array with one dem run per job, nothing run", "[campaign]") {
  const auto out = test::campaign_dir("slurm");
  auto opt = test::sweep_options("data/sweeps/tiny.toml", out);
  opt.processes = 2;
  opt.emit_slurm = true;
  campaign::run_sweep(opt);
  const std::string script = io::read_file(out / "sweep.slurm");
  CHECK_THAT(script,
             Catch::Contains("#SBATCH --array=0-2\n") && Catch::Contains("#SBATCH --ntasks=2\n"));
  CHECK_THAT(script,
             Catch::Contains(
                 "  1) \"$IWB\" dem run scenes/u10.toml --engine liggghts --np 2 --out runs/u10 "
                 "--consolidated consolidated $(resume runs/u10) ;;"));
  for (const std::string job : {"u0.05", "u10", "u0.1"}) {
    const std::string text = io::read_file(out / "scenes" / (job + ".toml"));
    CHECK(dem::parse_scene(text, job + ".toml").particle_count == 180);
  }
  CHECK(fs::is_directory(out / "logs"));
  CHECK_FALSE(fs::exists(out / "runs"));
  CHECK_FALSE(fs::exists(out / "sweep.json"));
  CHECK(std::system(("bash -n " + (out / "sweep.slurm").string()).c_str()) ==
        0);  // the script parses
}

TEST_CASE("sweep: a job's scene text does not depend on how the sweep file's path is spelled",
          "[campaign]") {
  // the text's sha256 decides reuse: running the same sweep from another directory must reuse it
  const auto relative = campaign::expand_jobs(campaign::load_sweep("data/sweeps/tiny.toml"));
  const auto absolute =
      campaign::expand_jobs(campaign::load_sweep(fs::absolute("data/sweeps/tiny.toml")));
  REQUIRE(relative.size() == absolute.size());
  for (std::size_t i = 0; i < relative.size(); ++i)
    CHECK(relative[i].scene_text == absolute[i].scene_text);
}

TEST_CASE(
    "sweep: [slurm] time takes Slurm's formats only, anything else is refused before a script is "
    "written",
    "[campaign]") {
  for (const char* ok :
       {"60", "90:30", "01:00:00", "48:00:00", "2-12", "2-12:30", "2-12:30:00", "0-1:5:9"})
    CHECK(campaign::is_slurm_time(ok));
  for (const char* bad :
       {"banana", "", "1:61:00", "1:00:61", "2-24", "2-1:60", "1h", "01:00:00 ", "-1", "1:2:3:4"})
    CHECK_FALSE(campaign::is_slurm_time(bad));
  const auto dir = test::campaign_dir("slurm_time");
  CHECK_THROWS_WITH(
      campaign::load_sweep(test::write_sweep(dir, "[slurm]\ntime = \"banana\"\n")),
      Catch::Contains(
          "key 'slurm.time' = \"banana\" is not a Slurm time; allowed MM, MM:SS, HH:MM:SS"));
  CHECK(
      campaign::load_sweep(test::write_sweep(dir, "[slurm]\ntime = \"1-00:00:00\"\n")).slurm_time ==
      "1-00:00:00");
}

TEST_CASE(
    "sweep: a wall file is found from a job's scene written elsewhere: the base's relative to the "
    "scene, "
    "the sweep's relative to the sweep file",
    "[campaign]") {
  const fs::path dir = fs::temp_directory_path() / "iwb_sweep_wall_files";
  fs::create_directories(dir);
  fs::copy_file("data/walls/sandblasted_like.csv", dir / "mine.csv",
                fs::copy_options::overwrite_existing);
  const std::string head =
      R"(scene = ")" + fs::absolute("data/scenes/smoke_file.toml").string() + R"("
engines = ["liggghts"]
[[axis]]
)";
  const auto scene_of = [&](const std::string& axis) {
    const auto jobs = campaign::expand_jobs(campaign::parse_sweep(head + axis, dir / "walls.toml"));
    REQUIRE(jobs.size() == 1);
    // parsed where no relative path would resolve: the job's scene holds an absolute path
    return dem::parse_scene(jobs[0].scene_text, "/nonexistent/scenes/job.toml");
  };
  CHECK(scene_of("key = \"wall.height_scale\"\nvalues = [4]\n").wall.file ==
        fs::absolute("data/walls/sandblasted_like.csv").lexically_normal().string());
  CHECK(scene_of("key = \"wall\"\nvalues = [{ profile = \"file\", file = \"mine.csv\", "
                 "height_scale = 4 }]\n")
            .wall.file == (dir / "mine.csv").lexically_normal().string());
  // a file names its job by its stem
  fs::create_directories(dir / "x");
  fs::copy_file(dir / "mine.csv", dir / "x" / "mine.csv", fs::copy_options::overwrite_existing);
  const auto named = campaign::expand_jobs(
      campaign::parse_sweep(head + "key = \"wall\"\nlabel = \"\"\nvalues = [{ profile = \"file\", "
                                   "file = \"../x/mine.csv\" }]\n",
                            dir / "sub" / "walls.toml"));
  CHECK(named.front().name == "file-mine");
}

TEST_CASE(
    "slurm options: a value Slurm would misread is refused naming the option, before anything is "
    "written",
    "[campaign]") {
  campaign::SlurmOptions ok;
  ok.time = "00:20:00";
  ok.partition = "short,long";
  ok.account = "geo_lab-1";
  ok.memory = "4G";
  ok.prologue = {"module load openmpi", "export OMP_NUM_THREADS=1"};
  CHECK_NOTHROW(campaign::check_slurm_options(ok));
  const auto refused = [&](auto change, const std::string& message) {
    auto o = ok;
    change(o);
    CHECK_THROWS_WITH(campaign::check_slurm_options(o),
                      Catch::Contains(message) && Catch::Contains("nothing was submitted"));
  };
  refused([](auto& o) { o.partition = "short long"; },
          "--partition 'short long': not a partition name");
  refused([](auto& o) { o.account = "lab;rm -rf"; }, "--account 'lab;rm -rf': not an account name");
  refused([](auto& o) { o.memory = "4GB"; }, "--mem '4GB': not a Slurm memory size");
  refused([](auto& o) { o.time = "1h"; }, "--time '1h': not one of Slurm's --time formats");
  refused([](auto& o) { o.prologue = {"#SBATCH --exclusive"}; },
          "--prologue '#SBATCH --exclusive'");
  // what reaches the script: each option as its #SBATCH line, the prologue before the jobs
  const auto jobs = campaign::expand_jobs(campaign::load_sweep("data/sweeps/tiny.toml"));
  ok.name = "iwb-tiny";
  const std::string script = campaign::slurm_script(jobs, ok, {"", "--resume", "--force"});
  CHECK_THAT(
      script,
      Catch::Contains(
          "#SBATCH --partition=short,long\n#SBATCH --account=geo_lab-1\n#SBATCH --mem=4G\n"));
  CHECK(script.find("module load openmpi\n") < script.find("case \"$SLURM_ARRAY_TASK_ID\""));
  CHECK_THAT(
      script,
      Catch::Contains("--out runs/u10 --consolidated consolidated --resume ;;") &&
          Catch::Contains("--out runs/u0.1 --consolidated consolidated --force ;;") &&
          Catch::Contains("--out runs/u0.05 --consolidated consolidated $(resume runs/u0.05) ;;"));
}

TEST_CASE(
    "slurm script: a job name the shell would read as code is single-quoted, the script still "
    "parses",
    "[campaign]") {
  campaign::SlurmOptions o;
  o.name = "iwb-x";
  o.time = "10";
  o.iwb = "/opt/my iwb/bin/iwb";
  const std::vector<campaign::Job> jobs = {{"plain_s1", "liggghts", {}, ""},
                                           {"a b;touch pwned", "liggghts", {}, ""}};
  const std::string script = campaign::slurm_script(jobs, o);
  CHECK_THAT(script, Catch::Contains("IWB=${IWB:-'/opt/my iwb/bin/iwb'}") &&
                         Catch::Contains("dem run scenes/plain_s1.toml") &&
                         Catch::Contains("dem run 'scenes/a b;touch pwned.toml' --engine liggghts "
                                         "--np 1 --out 'runs/a b;touch pwned'"));
  const auto dir = test::campaign_dir("slurm_quoting");
  io::write_atomically(dir / "q.slurm", script);
  CHECK(std::system(("bash -n " + (dir / "q.slurm").string()).c_str()) == 0);
}
