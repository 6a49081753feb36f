#include "ui/document/autosave.h"

#include <algorithm>
#include <cerrno>
#include <csignal>

#include <QCoreApplication>
#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QJsonDocument>
#include <QJsonObject>
#include <QStandardPaths>
#include <QTimer>

#include <unistd.h>

#include "core/util/atomic_file.h"

namespace mq::ui {
namespace {

bool processRunning(qint64 pid) { return pid > 0 && (kill(pid_t(pid), 0) == 0 || errno == EPERM); }

QString sidecarOf(const QString& copyPath) { return copyPath.chopped(QString(".mqscene").size()) + ".json"; }

}  // namespace

Autosave::Autosave(QString folder, Source source, QObject* parent)
    : QObject(parent), folder_(std::move(folder)), source_(std::move(source)) {
  timer_ = new QTimer(this);
  connect(timer_, &QTimer::timeout, this, [this] { saveNow(); });
}

void Autosave::start(int seconds) { timer_->start(std::max(1, seconds) * 1000); }

QString Autosave::copyPath() const {
  return QDir(folder_).filePath(QString::number(QCoreApplication::applicationPid()) + ".mqscene");
}

bool Autosave::saveNow() {
  if (!source_.modified()) {
    discard();
    return true;
  }
  lastError_.clear();
  if (!QDir().mkpath(folder_)) {
    lastError_ = tr("cannot create %1").arg(folder_);
    return false;
  }
  const QString path = copyPath();
  if (!source_.write(path, &lastError_)) return false;
  const QJsonObject about{{"document", source_.documentPath()},
                          {"written", QDateTime::currentDateTime().toString(Qt::ISODate)}};
  try {
    writeFileAtomically(sidecarOf(path).toStdString(),
                        [&](std::ostream& out) { out << QJsonDocument(about).toJson().toStdString(); });
  } catch (const std::exception& e) {
    lastError_ = QString::fromUtf8(e.what());
    return false;
  }
  return true;
}

void Autosave::discard() { remove({copyPath(), QString(), QDateTime()}); }

QString Autosave::defaultFolder() {
  const QString given = qEnvironmentVariable("MANNEQUIN_RECOVERY_DIR");
  if (!given.isEmpty()) return given;
  return QDir(QStandardPaths::writableLocation(QStandardPaths::AppLocalDataLocation)).filePath("recovery");
}

std::vector<RecoveryCopy> Autosave::leftBehind(const QString& folder) {
  std::vector<RecoveryCopy> copies;
  for (const QFileInfo& file : QDir(folder).entryInfoList({"*.mqscene"}, QDir::Files)) {
    bool isNumber = false;
    const qint64 pid = file.completeBaseName().toLongLong(&isNumber);
    if (!isNumber || processRunning(pid)) continue;
    RecoveryCopy copy{file.absoluteFilePath(), QString(), file.lastModified()};
    QFile sidecar(sidecarOf(copy.copyPath));
    if (sidecar.open(QIODevice::ReadOnly)) {
      const QJsonObject about = QJsonDocument::fromJson(sidecar.readAll()).object();
      copy.documentPath = about.value("document").toString();
      const QDateTime written = QDateTime::fromString(about.value("written").toString(), Qt::ISODate);
      if (written.isValid()) copy.written = written;
    }
    copies.push_back(copy);
  }
  std::sort(copies.begin(), copies.end(),
            [](const RecoveryCopy& a, const RecoveryCopy& b) { return a.written > b.written; });
  return copies;
}

void Autosave::remove(const RecoveryCopy& copy) {
  QFile::remove(copy.copyPath);
  QFile::remove(sidecarOf(copy.copyPath));
}

}  // namespace mq::ui
