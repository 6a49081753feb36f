#pragma once
// The hair tool's work off the GUI thread: regrowing the groom for a style
// and building the arrays the viewport draws (regrow), or recomputing the
// self-shadow for a new key light or new shadow settings (reshade). One job
// runs at a time on Qt's global thread pool. A request replaces an older one
// that has not started, and the result of a job overtaken by a newer regrow
// is dropped, so the viewport keeps the last finished hair until the newest
// is ready. Results are handed over on the GUI thread (onRegrown,
// onReshaded), where only pointer swaps remain to be done.

#include <cstdint>
#include <functional>
#include <memory>
#include <optional>

#include <QFuture>
#include <QFutureWatcher>
#include <QObject>

#include <glm/glm.hpp>

#include "core/hair/hairstyle.h"
#include "render/hair_actor.h"

namespace mq {
class HairGroom;
}

namespace mq::ui {

// What a change from the groom grown for `grown` (with `grownStrands`; its
// children following its guides or not) to `style` with `strands` regrows.
enum class Regrowth { Nothing, Children, GuidesAndChildren, Everything };
Regrowth regrowthNeeded(const std::optional<HairStyle>& grown, size_t grownStrands, bool childrenCurrent,
                        const HairStyle& style, size_t strands);

class HairWorker : public QObject {
  Q_OBJECT

 public:
  struct RegrowRequest {
    // The groom to start from (never modified: the job grows a copy), and
    // the style and strand count it was grown with (none: not grown yet).
    std::shared_ptr<const HairGroom> groom;
    std::optional<HairStyle> grownStyle;
    size_t grownStrands = 0;
    bool childrenCurrent = false;
    HairStyle style;
    size_t strands = 0;
    bool live = false;  // a drag step: the guides alone regrow and are shown
    glm::mat4 posedFromRest{1.0f};
    render::HairShading shading;
    std::optional<glm::vec3> keyLight;  // the shadow's light (none: lit until reshaded)
  };
  struct Regrown {
    std::shared_ptr<const HairGroom> groom;
    HairStyle style;
    size_t strands = 0;
    bool childrenCurrent = false;
    bool guidesOnly = false;
    glm::mat4 posedFromRest{1.0f};
    std::shared_ptr<const render::HairGeometry> geometry;
    double seconds = 0.0;  // the job's wall time
  };

  explicit HairWorker(QObject* parent = nullptr);
  ~HairWorker() override;

  void regrow(RegrowRequest request);
  // Recomputes `geometry`'s shadow; dropped when a regrow comes first.
  void reshade(std::shared_ptr<const render::HairGeometry> geometry, const render::HairShading& shading,
               const glm::vec3& keyLight);
  // Forgets every request; a running job's result is dropped.
  void cancel();
  bool busy() const { return running_ || pendingRegrow_ || pendingReshade_; }
  // Runs the jobs and their hand-offs until none is left (GUI thread; for
  // scripts, screenshots and the bake, which need the current hair).
  void finish();

  std::function<void(const Regrown&)> onRegrown;
  // (the geometry reshaded, the result): the caller shows the result when it
  // still shows the geometry.
  std::function<void(const std::shared_ptr<const render::HairGeometry>&,
                     const std::shared_ptr<const render::HairGeometry>&)>
      onReshaded;
  std::function<void(bool busy)> onBusyChanged;

 private:
  struct Reshade {
    std::shared_ptr<const render::HairGeometry> geometry;
    render::HairShading shading;
    glm::vec3 keyLight;
  };
  void startNext();
  void jobFinished();
  void setBusy();

  // The newest regrow; a result is kept only when its generation is still
  // the newest.
  uint64_t generation_ = 0;
  std::optional<RegrowRequest> pendingRegrow_;
  std::optional<Reshade> pendingReshade_;
  bool running_ = false;
  bool reportedBusy_ = false;
  // The running job returns its hand-off, which checks its generation.
  QFuture<std::function<void()>> future_;
  QFutureWatcher<std::function<void()>> watcher_;
};

}  // namespace mq::ui
