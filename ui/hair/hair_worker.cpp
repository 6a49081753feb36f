#include "ui/hair/hair_worker.h"

#include <chrono>

#include <QtConcurrent/QtConcurrentRun>
#include <nlohmann/json.hpp>

#include "core/hair/hair_groom.h"
#include "core/hair/hairstyle_json.h"
#include "sim/hair/child_follow.h"

namespace mq::ui {

namespace {

bool rootsDiffer(const HairStyle& a, const HairStyle& b) {
  return a.density != b.density || a.maxStrands != b.maxStrands || a.guideCount != b.guideCount || a.seed != b.seed ||
         a.pointsPerStrand != b.pointsPerStrand ||
         strokesOf(a.strokes, GroomBrush::PaintDensity) != strokesOf(b.strokes, GroomBrush::PaintDensity);
}

// Colours and shading are shader uniforms: the strands stay.
bool onlyColorsDiffer(HairStyle a, const HairStyle& b) {
  a.rootColor = b.rootColor;
  a.tipColor = b.tipColor;
  a.shading = b.shading;
  a.dynamics = b.dynamics;  // the simulation's, not the groom's
  return toJson(a) == toJson(b);
}

// The whole regrow, on a worker thread: the least regrowth the change
// needs, then the arrays of the strands where the head is now.
HairWorker::Regrown regrowAndPrepare(const HairWorker::RegrowRequest& request) {
  const auto start = std::chrono::steady_clock::now();
  auto groom = std::make_shared<HairGroom>(*request.groom);
  bool childrenCurrent = request.childrenCurrent;
  switch (regrowthNeeded(request.grownStyle, request.grownStrands, request.childrenCurrent, request.style,
                         request.strands)) {
    case Regrowth::Everything:
      groom->grow(request.style, request.strands);
      childrenCurrent = true;
      break;
    case Regrowth::GuidesAndChildren:
      groom->regrowGuides(request.style);
      childrenCurrent = false;
      [[fallthrough]];
    case Regrowth::Children:
      if (!request.live) {  // a drag's steps show the guides alone
        groom->growChildren(request.style);
        childrenCurrent = true;
      }
      break;
    case Regrowth::Nothing:
      break;
  }
  const Strands& all = groom->strands();
  auto shown = std::make_shared<Strands>(request.live ? leadingStrands(all, groom->guideCount()) : all);
  if (request.posedFromRest != glm::mat4(1.0f)) {
    std::vector<float>& p = shown->points;
    for (size_t k = 0; k + 2 < p.size(); k += 3) {
      const glm::vec3 posed = glm::vec3(request.posedFromRest * glm::vec4(p[k], p[k + 1], p[k + 2], 1.0f));
      p[k] = posed.x;
      p[k + 1] = posed.y;
      p[k + 2] = posed.z;
    }
  }
  HairWorker::Regrown result;
  result.geometry = render::HairActor::prepareGeometry(std::move(shown), request.shading, request.keyLight);
  result.groom = std::move(groom);
  result.style = request.style;
  result.strands = request.strands;
  result.childrenCurrent = childrenCurrent;
  result.guidesOnly = request.live;
  result.posedFromRest = request.posedFromRest;
  result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return result;
}

}  // namespace

// Roots are kept unless the counts or the seed changed; a colour is a
// uniform of the shader.
Regrowth regrowthNeeded(const std::optional<HairStyle>& grown, size_t grownStrands, bool childrenCurrent,
                        const HairStyle& style, size_t strands) {
  if (!grown || grownStrands != strands || rootsDiffer(*grown, style)) return Regrowth::Everything;
  if (!onlyColorsDiffer(*grown, style)) return Regrowth::GuidesAndChildren;
  return childrenCurrent ? Regrowth::Nothing : Regrowth::Children;
}

HairWorker::HairWorker(QObject* parent) : QObject(parent) {
  connect(&watcher_, &QFutureWatcher<std::function<void()>>::finished, this, &HairWorker::jobFinished);
}

// A job must not outlive the pools it uses (ThreadPool::shared()).
HairWorker::~HairWorker() { future_.waitForFinished(); }

void HairWorker::regrow(RegrowRequest request) {
  ++generation_;
  pendingRegrow_ = std::move(request);
  pendingReshade_.reset();  // the new arrays come with their shadow
  startNext();
  setBusy();
}

void HairWorker::reshade(std::shared_ptr<const render::HairGeometry> geometry, const render::HairShading& shading,
                         const glm::vec3& keyLight) {
  pendingReshade_ = Reshade{std::move(geometry), shading, keyLight};
  startNext();
  setBusy();
}

void HairWorker::cancel() {
  ++generation_;
  pendingRegrow_.reset();
  pendingReshade_.reset();
  setBusy();
}

void HairWorker::startNext() {
  if (running_) return;
  const uint64_t generation = generation_;
  if (pendingRegrow_) {
    RegrowRequest request = std::move(*pendingRegrow_);
    pendingRegrow_.reset();
    future_ = QtConcurrent::run([this, request = std::move(request), generation]() -> std::function<void()> {
      auto result = std::make_shared<Regrown>(regrowAndPrepare(request));
      // Runs on the GUI thread (jobFinished); `this` outlives the job.
      return [this, result, generation] {
        if (generation == generation_ && onRegrown) onRegrown(*result);
      };
    });
  } else if (pendingReshade_) {
    Reshade job = std::move(*pendingReshade_);
    pendingReshade_.reset();
    future_ = QtConcurrent::run([this, job = std::move(job), generation]() -> std::function<void()> {
      auto reshaded = render::HairActor::reshade(job.geometry, job.shading, job.keyLight);
      return [this, source = job.geometry, reshaded, generation] {
        if (generation == generation_ && onReshaded) onReshaded(source, reshaded);
      };
    });
  } else {
    return;
  }
  running_ = true;
  watcher_.setFuture(future_);
}

void HairWorker::jobFinished() {
  if (!running_ || !future_.isFinished()) return;  // handed off already by finish()
  running_ = false;
  const std::function<void()> handOff = future_.result();
  future_ = {};
  handOff();
  startNext();
  setBusy();
}

void HairWorker::finish() {
  while (running_) {
    future_.waitForFinished();
    jobFinished();
  }
}

void HairWorker::setBusy() {
  if (busy() == reportedBusy_) return;
  reportedBusy_ = busy();
  if (onBusyChanged) onBusyChanged(reportedBusy_);
}

}  // namespace mq::ui
