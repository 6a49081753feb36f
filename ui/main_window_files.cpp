// MainWindow's file handling: opening on a worker thread, motions, saving,
// exporting, recent files, progress, drag and drop, closing.
#include "ui/main_window.h"

#include <iostream>

#include <variant>

#include <QAction>
#include <QApplication>
#include <QCloseEvent>
#include <QDir>
#include <QElapsedTimer>
#include <QFileDialog>
#include <QFileInfo>
#include <QFutureWatcher>
#include <QLocale>
#include <QMenu>
#include <QMessageBox>
#include <QMimeData>
#include <QProgressBar>
#include <QSettings>
#include <QStandardPaths>
#include <QStatusBar>
#include <QUndoStack>
#include <QtConcurrent/QtConcurrentRun>

#include "core/io/json_fields.h"
#include "core/io/mesh_export.h"
#include "core/io/rigged_export.h"
#include "render/scene_view.h"
#include "sim/cloth/point_cache.h"
#include "ui/document/autosave.h"
#include "ui/document/document_loader.h"
#include "ui/document/editor_document.h"
#include "ui/document/motion_commands.h"
#include "ui/export/export_animated_dialog.h"
#include "ui/garment/garment_tool.h"
#include "ui/hair/hair_tool.h"
#include "ui/motion/apply_motion_dialog.h"

namespace mq::ui {
namespace {

constexpr int kMaxRecentFiles = 8;
const char* kRecentFilesKey = "recentFiles";
const char* kLastAnimatedExportKey = "lastAnimatedExport";

// What a worker thread hands back: the result or the error text.
template <typename T>
using Outcome = std::variant<T, QString>;

template <typename T, typename Work>
Outcome<T> runCatching(Work work) {
  try {
    return work();
  } catch (const std::exception& e) {
    return QString::fromStdString(jsonProblem(e));  // never a library's exception tag
  }
}

}  // namespace

// --- files -----------------------------------------------------------------------------

bool MainWindow::maybeDiscardChanges() {
  return !document_->isModified() || !confirmDiscardChanges || confirmDiscardChanges();
}

void MainWindow::newDocument() { openFile("default"); }

void MainWindow::openWithDialog() {
  QSettings settings;
  const QString start = settings.value("lastDirectory").toString();
  const QString path = QFileDialog::getOpenFileName(this, tr("Open"), start, openFileFilter());
  if (path.isEmpty()) return;
  settings.setValue("lastDirectory", QFileInfo(path).absolutePath());
  openFile(path);
}

void MainWindow::setBusy(bool busy, const QString& message) {
  busy_ = busy;
  progress_->setRange(0, 0);  // busy indicator: the loaders report no fraction
  progress_->setVisible(busy);
  for (QAction* a :
       {newAction_, openAction_, applyMotionAction_, saveAction_, saveAsAction_, exportAction_, exportAnimatedAction_})
    a->setEnabled(!busy);
  recentMenu_->setEnabled(!busy);
  if (busy)
    QApplication::setOverrideCursor(Qt::BusyCursor);
  else
    QApplication::restoreOverrideCursor();
  statusBar()->showMessage(message, busy ? 0 : 8000);
  emit busyChanged(busy);
}

void MainWindow::showProgress(const QString& message, int percent) {
  if (percent < 0)
    progress_->setRange(0, 0);
  else {
    progress_->setRange(0, 100);
    progress_->setValue(percent);
  }
  progress_->setVisible(true);
  statusBar()->showMessage(message);
}

void MainWindow::hideProgress(const QString& message) {
  progress_->setVisible(busy_);
  if (message.isEmpty())
    statusBar()->clearMessage();
  else
    statusBar()->showMessage(message, 8000);
}

void MainWindow::openFile(const QString& fileOrDefault) {
  if (busy_) return;
  if (isMotionFile(fileOrDefault)) {
    applyMotion(fileOrDefault);
    return;
  }
  const QString shown = fileOrDefault == "default" ? tr("the default mannequin") : QFileInfo(fileOrDefault).fileName();
  setBusy(true, tr("Opening %1...").arg(shown));
  auto clock = std::make_shared<QElapsedTimer>();
  clock->start();

  auto* watcher = new QFutureWatcher<Outcome<LoadedDocument>>(this);
  connect(watcher, &QFutureWatcherBase::finished, this, [this, watcher, fileOrDefault, clock] {
    Outcome<LoadedDocument> outcome = watcher->future().takeResult();
    watcher->deleteLater();
    setBusy(false, QString());
    if (auto* error = std::get_if<QString>(&outcome)) {
      statusBar()->showMessage(tr("Could not open %1").arg(fileOrDefault), 8000);
      if (reportError) reportError(tr("Could not open the file"), *error);
      emit loadFinished(false);
      return;
    }
    // Asked only now that the new file has been read: a file that fails to
    // open costs the open document nothing.
    if (!maybeDiscardChanges()) {
      statusBar()->showMessage(tr("Kept the open document; %1 was not opened").arg(fileOrDefault), 8000);
      emit loadFinished(false);
      return;
    }
    const bool isRecoveryCopy =
        autosave_ && QFileInfo(fileOrDefault).absolutePath() == QDir(autosave_->folder()).absolutePath();
    if (fileOrDefault != "default" && !isRecoveryCopy) addRecentFile(fileOrDefault);
    adoptLoaded(std::move(std::get<LoadedDocument>(outcome)), clock->elapsed() / 1000.0);
    emit loadFinished(true);
  });
  watcher->setFuture(QtConcurrent::run(
      [fileOrDefault] { return runCatching<LoadedDocument>([&] { return loadDocument(fileOrDefault); }); }));
}

void MainWindow::applyMotion(const QString& bvhPath, const QString& nameMapPath, bool inPlace) {
  if (busy_) return;
  setBusy(true, tr("Applying %1...").arg(QFileInfo(bvhPath).fileName()));
  auto clock = std::make_shared<QElapsedTimer>();
  clock->start();
  auto* watcher = new QFutureWatcher<Outcome<LoadedMotion>>(this);
  connect(watcher, &QFutureWatcherBase::finished, this, [this, watcher, bvhPath, clock] {
    Outcome<LoadedMotion> outcome = watcher->future().takeResult();
    watcher->deleteLater();
    setBusy(false, QString());
    if (auto* error = std::get_if<QString>(&outcome)) {
      statusBar()->showMessage(tr("Could not apply %1").arg(bvhPath), 8000);
      if (reportError) reportError(tr("Could not apply the motion"), *error);
      emit loadFinished(false);
      return;
    }
    addRecentFile(bvhPath);
    adoptMotion(std::move(std::get<LoadedMotion>(outcome)), clock->elapsed() / 1000.0);
    emit loadFinished(true);
  });
  const Character target = document_->character();
  watcher->setFuture(QtConcurrent::run([bvhPath, nameMapPath, inPlace, target] {
    return runCatching<LoadedMotion>([&] { return loadMotion(bvhPath, target, nameMapPath, inPlace); });
  }));
}

void MainWindow::applyMotionWithDialog() {
  auto* dialog = new ApplyMotionDialog(document_->character(), this);
  dialog->setAttribute(Qt::WA_DeleteOnClose);
  connect(dialog, &QDialog::accepted, this,
          [this, dialog] { applyMotion(dialog->motionFile(), dialog->nameMapFile(), dialog->inPlace()); });
  dialog->open();
}

void MainWindow::adoptMotion(LoadedMotion loaded, double seconds) {
  const BoneMatchReport match = loaded.motion.match;
  const QString name = QString::fromStdString(loaded.motion.clip.name);
  MotionRecord record{loaded.bvhPath.toStdString(), loaded.nameMapPath.toStdString(), loaded.inPlace};
  document_->undoStack()->push(new ApplyMotionCommand(document_, std::move(loaded.motion.clip), std::move(record)));
  // The whole report on the terminal, a short one in the status bar.
  std::cerr << "motion " << loaded.bvhPath.toStdString() << ": " << match.summary() << "\n";
  statusBar()->showMessage(tr("Applied motion %1 (%2 s): %3")
                               .arg(name)
                               .arg(seconds, 0, 'f', 2)
                               .arg(QString::fromStdString(match.summary(6))),
                           15000);
}

bool MainWindow::openFileNow(const QString& fileOrDefault, QString* error) {
  QElapsedTimer clock;
  clock.start();
  try {
    if (isMotionFile(fileOrDefault)) {
      adoptMotion(loadMotion(fileOrDefault, document_->character()), clock.elapsed() / 1000.0);
    } else {
      adoptLoaded(loadDocument(fileOrDefault), clock.elapsed() / 1000.0);
    }
    emit loadFinished(true);
    return true;
  } catch (const std::exception& e) {
    if (error) *error = QString::fromUtf8(e.what());
    emit loadFinished(false);
    return false;
  }
}

void MainWindow::adoptLoaded(LoadedDocument loaded, double seconds) {
  // A new character shows its skeleton so it can be posed at once.
  if (loaded.documentPath.isEmpty()) loaded.scene.view.showSkeleton = true;
  const QString name = loaded.displayName;
  document_->replace(std::move(loaded));
  // Problems worked around while loading (a missing texture): printed in
  // full, and the first one shown with the open message.
  std::vector<std::string> warnings = document_->character().loadWarnings;
  if (!document_->character().unitNotice.empty() && document_->sceneSections().scale == 1.0f)
    warnings.push_back(document_->character().unitNotice);
  for (const std::string& w : scene_->warnings()) warnings.push_back(w);
  for (const std::string& w : warnings) std::cerr << "warning: " << w << "\n";
  const QString more = warnings.empty()
                           ? QString()
                           : tr("; warning: %1%2")
                                 .arg(QString::fromStdString(warnings.front()),
                                      warnings.size() > 1 ? tr(" (and %1 more)").arg(warnings.size() - 1) : QString());
  statusBar()->showMessage(
      tr("Opened %1: %2 (%3 s)%4").arg(name, document_->summary()).arg(seconds, 0, 'f', 2).arg(more),
      warnings.empty() ? 8000 : 20000);
}

bool MainWindow::writeSceneTo(const QString& path, bool absolutePaths, QString* error) {
  storeCamera();
  SceneDocument scene = document_->sceneDocument();
  // Files the document refers to are stored relative to it.
  const QDir folder = QFileInfo(path).absoluteDir();
  const QDir oldFolder =
      document_->documentPath().isEmpty() ? QDir::current() : QFileInfo(document_->documentPath()).absoluteDir();
  auto place = [&](std::string& stored) {
    if (stored.empty() || stored == "default") return;
    const QString absolute = oldFolder.absoluteFilePath(QString::fromStdString(stored));
    stored = (absolutePaths ? QDir::cleanPath(absolute) : folder.relativeFilePath(absolute)).toStdString();
  };
  place(scene.character);
  place(scene.motionFile);
  place(scene.motionMapFile);
  try {
    saveSceneDocument(scene, path.toStdString());
  } catch (const std::exception& e) {
    if (error) *error = QString::fromUtf8(e.what());
    return false;
  }
  return true;
}

bool MainWindow::saveDocument(const QString& path, QString* error) {
  if (!writeSceneTo(path, false, error)) return false;
  document_->setDocumentPath(QFileInfo(path).absoluteFilePath());
  document_->markSaved();
  if (autosave_) autosave_->discard();
  addRecentFile(path);
  updateTitle();
  statusBar()->showMessage(tr("Saved %1").arg(path), 5000);
  emit documentSaved(document_->documentPath());
  return true;
}

void MainWindow::enableAutosave(const QString& folder, int seconds) {
  delete autosave_;
  Autosave::Source source;
  source.write = [this](const QString& path, QString* error) { return writeSceneTo(path, true, error); };
  source.modified = [this] { return document_->isModified(); };
  source.documentPath = [this] { return document_->documentPath(); };
  autosave_ = new Autosave(folder, std::move(source), this);
  autosave_->start(seconds);
}

bool MainWindow::offerRecovery() {
  if (!autosave_ || busy_) return false;
  const std::vector<RecoveryCopy> copies = Autosave::leftBehind(autosave_->folder());
  if (copies.empty()) return false;
  const RecoveryCopy copy = copies.front();
  const QString name =
      copy.documentPath.isEmpty() ? tr("an untitled document") : QFileInfo(copy.documentPath).fileName();
  const bool restore =
      confirmRecovery ? confirmRecovery(copy)
                      : QMessageBox::question(this, tr("Restore unsaved changes?"),
                                              tr("Mannequin did not close properly. Restore the "
                                                 "changes to %1 kept at %2?")
                                                  .arg(name, QLocale().toString(copy.written, QLocale::ShortFormat)),
                                              QMessageBox::Yes | QMessageBox::No) == QMessageBox::Yes;
  if (!restore) {
    Autosave::remove(copy);
    return false;
  }
  connect(
      this, &MainWindow::loadFinished, this,
      [this, copy](bool ok) {
        if (!ok) return;  // the copy stays for another try; the error was reported
        document_->setDocumentPath(copy.documentPath.isEmpty() ? QString()
                                                               : QFileInfo(copy.documentPath).absoluteFilePath());
        document_->notifyChanged();  // restored changes are still unsaved
        Autosave::remove(copy);
        autosave_->saveNow();  // now this process keeps them
        updateTitle();
        statusBar()->showMessage(tr("Restored the unsaved changes to %1")
                                     .arg(copy.documentPath.isEmpty() ? tr("an untitled document") : copy.documentPath),
                                 8000);
      },
      Qt::SingleShotConnection);
  openFile(copy.copyPath);
  return true;
}

bool MainWindow::save() {
  if (document_->documentPath().isEmpty()) return saveAs();
  QString error;
  if (saveDocument(document_->documentPath(), &error)) return true;
  if (reportError) reportError(tr("Could not save"), error);
  return false;
}

QString MainWindow::saveAsProposal(const QString& documentPath, const QString& characterName,
                                   const QString& documentsDir) {
  const QFileInfo current(documentPath);
  const QString folder = current.absolutePath();
  const bool example = QDir::fromNativeSeparators(folder).endsWith("/resources/scenes");
  if (!documentPath.isEmpty() && !example && QFileInfo(folder).isWritable()) return documentPath;
  const QString name = documentPath.isEmpty() ? (characterName.isEmpty() ? QString("scene") : characterName)
                                              : current.completeBaseName();
  return QDir(documentsDir).filePath(name + ".mqscene");
}

bool MainWindow::saveAs() {
  const QString start = saveAsProposal(document_->documentPath(), QString::fromStdString(document_->character().name),
                                       QStandardPaths::writableLocation(QStandardPaths::DocumentsLocation));
  QString path = QFileDialog::getSaveFileName(this, tr("Save Scene"), start, saveSceneFilter());
  if (path.isEmpty()) return false;
  if (QFileInfo(path).suffix().isEmpty()) path += ".mqscene";
  QString error;
  if (saveDocument(path, &error)) return true;
  if (reportError) reportError(tr("Could not save"), error);
  return false;
}

bool MainWindow::exportPosedMesh(const QString& path, QString* error) {
  const Character& character = document_->character();
  std::vector<const Mesh*> meshes;
  for (const Mesh& m : character.meshes) meshes.push_back(&m);
  try {
    mq::exportPosedMesh(meshes, document_->posed().meshes(), path.toStdString(), &character);
  } catch (const std::exception& e) {
    if (error) *error = QString::fromUtf8(e.what());
    return false;
  }
  statusBar()->showMessage(tr("Exported %1").arg(path), 5000);
  return true;
}

void MainWindow::exportWithDialog() {
  QString filter;
  QString path = QFileDialog::getSaveFileName(this, tr("Export Posed Mesh"), QString(), exportMeshFilter(), &filter);
  if (path.isEmpty()) return;
  if (QFileInfo(path).suffix().isEmpty()) path += filter.contains("ply") ? ".ply" : ".obj";
  QString error;
  if (!exportPosedMesh(path, &error) && reportError) reportError(tr("Could not export"), error);
}

namespace {

std::vector<float> frameTimes(float start, float fps, int frames) {
  std::vector<float> times;
  for (int f = 0; f < frames; ++f) times.push_back(start + f / fps);
  return times;
}

}  // namespace

QString MainWindow::exportAnimatedGltf(const QString& path, QString* error) {
  const auto* garments = findChild<GarmentTool*>();
  const auto* hair = findChild<HairTool*>();
  ExportAnimatedChoice choice;
  choice.path = path;
  choice.garments = garments && garments->bakeForExport();
  choice.hair = hair && hair->hasBake();
  choice.take = choice.garments || choice.hair;
  return exportAnimated(choice, error);
}

QString MainWindow::exportAnimated(const ExportAnimatedChoice& choice, QString* error) {
  const Character& character = document_->character();
  const auto* garments = findChild<GarmentTool*>();
  const auto* hair = findChild<HairTool*>();
  const std::optional<GarmentTool::BakeForExport> cloth =
      choice.take && choice.garments && garments ? garments->bakeForExport() : std::nullopt;
  const bool hairBaked = choice.take && choice.hair && hair && hair->hasBake();
  RiggedExportOptions options;
  options.fps = choice.clipFps;
  // The bakes play as one take on the time axis of the garment bake, or of
  // the hair bake alone; without a bake, every clip is written.
  if (cloth || hairBaked) {
    ExportTake take;
    take.clip = cloth ? cloth->clip : document_->clipIndex();
    take.start = cloth ? cloth->start : hair->bakeStart();
    take.fps = cloth ? cloth->fps : hair->bakeFps();
    take.frames = cloth ? cloth->frames : hair->bakeFrameCount();
    take.name = take.clip >= 0 && take.clip < int(character.clips.size()) ? character.clips[take.clip].name : "rest";
    take.edits = &document_->poseEdits();
    options.take = take;
    if (cloth) options.baked = cloth->surfaces;
    if (hairBaked) options.baked.push_back(*hair->bakedGuides(frameTimes(take.start, take.fps, take.frames)));
  } else if (choice.take) {
    if (error) *error = tr("There is no garment or hair bake to export: bake first, or export every clip");
    return QString();
  }
  std::vector<std::string> warnings;
  std::vector<std::string> caches;
  try {
    warnings = exportRiggedCharacter(character, choice.path.toStdString(), options);
    if (options.take && !choice.pointCache.isEmpty()) {
      const QFileInfo gltf(choice.path);
      const QString cachePath = gltf.dir().filePath(gltf.completeBaseName() + "." + choice.pointCache);
      caches = cloth::writeSurfacePointCaches(options.baked, cachePath.toStdString(), options.take->fps);
    }
  } catch (const std::exception& e) {
    if (error) *error = QString::fromUtf8(e.what());
    return QString();
  }
  QString summary =
      options.take ? tr("%1 frames of %2").arg(options.take->frames).arg(QString::fromStdString(options.take->name))
                   : tr("%n clip(s)", "", int(character.clips.size()));
  for (const BakedSurface& s : options.baked) summary += ", " + QString::fromStdString(s.name);
  if (!caches.empty()) summary += tr(", %n point cache(s)", "", int(caches.size()));
  for (const std::string& w : warnings) summary += "; " + QString::fromStdString(w);
  statusBar()->showMessage(tr("Exported %1 (%2)").arg(choice.path, summary), 8000);
  return summary;
}

ExportAnimatedSources MainWindow::exportAnimatedSources() const {
  ExportAnimatedSources sources;
  sources.clipCount = int(document_->character().clips.size());
  const auto* garments = findChild<GarmentTool*>();
  const auto* hair = findChild<HairTool*>();
  if (const auto cloth = garments ? garments->bakeForExport() : std::nullopt)
    sources.garmentBake = tr("%1 frames at %2 fps, %3 %4")
                              .arg(cloth->frames)
                              .arg(double(cloth->fps))
                              .arg(cloth->surfaces.size())
                              .arg(cloth->surfaces.size() == 1 ? tr("surface") : tr("surfaces"));
  if (hair && hair->hasBake())
    sources.hairBake = tr("%1 frames at %2 fps").arg(hair->bakeFrameCount()).arg(double(hair->bakeFps()));
  return sources;
}

void MainWindow::exportAnimatedWithDialog() {
  QSettings settings;
  QString path = settings.value(kLastAnimatedExportKey).toString();
  if (path.isEmpty())
    path = QDir(QStandardPaths::writableLocation(QStandardPaths::DocumentsLocation))
               .filePath(QString::fromStdString(document_->character().name).simplified().replace(' ', '_') + ".glb");
  ExportAnimatedDialog dialog(exportAnimatedSources(), path, this);
  if (dialog.exec() != QDialog::Accepted) return;
  const ExportAnimatedChoice choice = dialog.choice();
  settings.setValue(kLastAnimatedExportKey, choice.path);
  QString error;
  if (exportAnimated(choice, &error).isEmpty() && reportError) reportError(tr("Could not export"), error);
}

void MainWindow::addRecentFile(const QString& path) {
  QSettings settings;
  QStringList files = settings.value(kRecentFilesKey).toStringList();
  const QString absolute = QFileInfo(path).absoluteFilePath();
  files.removeAll(absolute);
  files.prepend(absolute);
  while (files.size() > kMaxRecentFiles) files.removeLast();
  settings.setValue(kRecentFilesKey, files);
  rebuildRecentMenu();
}

void MainWindow::rebuildRecentMenu() {
  recentMenu_->clear();
  const QStringList files = QSettings().value(kRecentFilesKey).toStringList();
  for (const QString& file : files) {
    QAction* action = recentMenu_->addAction(QFileInfo(file).fileName());
    action->setToolTip(file);
    connect(action, &QAction::triggered, this, [this, file] { openFile(file); });
  }
  recentMenu_->setEnabled(!files.isEmpty() && !busy_);
}

// --- window events ------------------------------------------------------------------

void MainWindow::closeEvent(QCloseEvent* event) {
  if (busy_ || !maybeDiscardChanges()) {
    event->ignore();
    return;
  }
  if (autosave_) autosave_->discard();
  QSettings settings;
  settings.setValue("window/geometry", saveGeometry());
  settings.setValue("window/state", saveState());
  event->accept();
}

void MainWindow::restoreWindowState() {
  QSettings settings;
  restoreGeometry(settings.value("window/geometry").toByteArray());
  restoreState(settings.value("window/state").toByteArray());
}

void MainWindow::dragEnterEvent(QDragEnterEvent* event) {
  const QMimeData* mime = event->mimeData();
  if (!mime->hasUrls()) return;
  for (const QUrl& url : mime->urls())
    if (url.isLocalFile() && isOpenableFile(url.toLocalFile())) {
      event->acceptProposedAction();
      return;
    }
}

void MainWindow::dropEvent(QDropEvent* event) {
  for (const QUrl& url : event->mimeData()->urls()) {
    const QString path = url.toLocalFile();
    if (!isOpenableFile(path)) continue;
    event->acceptProposedAction();
    openFile(path);
    return;
  }
}

}  // namespace mq::ui
