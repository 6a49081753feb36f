#pragma once
// Recovery copies of a modified document, so that a crash or a kill loses at
// most a minute of work. Each editor process writes its copy to
// FOLDER/<pid>.mqscene (with FOLDER/<pid>.json naming the document it stands
// for) while the document has unsaved changes; a save or a clean exit
// removes it. At the next start, copies left by processes that are no longer
// running are offered for restoring.

#include <functional>
#include <vector>

#include <QDateTime>
#include <QObject>
#include <QString>

class QTimer;

namespace mq::ui {

struct RecoveryCopy {
  QString copyPath;      // FOLDER/<pid>.mqscene
  QString documentPath;  // the document it was made from; empty: never saved
  QDateTime written;
};

class Autosave : public QObject {
  Q_OBJECT

 public:
  // What is saved, asked of the editor.
  struct Source {
    // Writes the document to `path` (false and `error` on failure).
    std::function<bool(const QString& path, QString* error)> write;
    // Whether there are unsaved changes to keep.
    std::function<bool()> modified;
    // The document's own path (empty: never saved).
    std::function<QString()> documentPath;
  };
  Autosave(QString folder, Source source, QObject* parent = nullptr);

  // Writes a copy every `seconds` while modified.
  void start(int seconds);
  // Writes the copy now when modified (before long work), else removes it.
  bool saveNow();
  // Removes this process's copy (after a save, at a clean exit).
  void discard();

  QString copyPath() const;
  const QString& folder() const { return folder_; }
  const QString& lastError() const { return lastError_; }

  // AppLocalDataLocation/recovery, or $MANNEQUIN_RECOVERY_DIR.
  static QString defaultFolder();
  // Copies whose process is gone, newest first.
  static std::vector<RecoveryCopy> leftBehind(const QString& folder);
  static void remove(const RecoveryCopy& copy);

 private:
  QString folder_;
  Source source_;
  QString lastError_;
  QTimer* timer_ = nullptr;
};

}  // namespace mq::ui
