// No work lost: an editor killed (SIGKILL) after an edit leaves a recovery
// copy, and the next start restores the edit as unsaved changes; a clean
// close and a save remove the copy. Run as `mannequin_gui_tests recovery`.
#include <QFile>
#include <QProcess>
#include <QSignalSpy>
#include <QTemporaryDir>

#include "test_window.h"
#include "ui/document/autosave.h"
#include "ui/document/editor_document.h"

using namespace mq;
using namespace mq::ui;

namespace {

class RecoveryTest : public QObject {
  Q_OBJECT

 private slots:
  void killedEditorsEditIsRestored() {
    QTemporaryDir folder;
    QVERIFY(folder.isValid());
    // The real editor, as a user starts it, adding a skirt (an edit), then killed.
    QProcess editor;
    QProcessEnvironment environment = QProcessEnvironment::systemEnvironment();
    environment.insert("MANNEQUIN_RECOVERY_DIR", folder.path());
    environment.insert("MANNEQUIN_AUTOSAVE_SECONDS", "1");
    editor.setProcessEnvironment(environment);
    editor.setProcessChannelMode(QProcess::ForwardedChannels);
    editor.start(QString(MANNEQUIN_BINARY_DIR) + "/app/mannequin",
                 {"default", "--add-garment", "skirt", "--size", "800x600"});
    QVERIFY(editor.waitForStarted());
    const QString copy = folder.filePath(QString::number(editor.processId()) + ".mqscene");
    const QString about = folder.filePath(QString::number(editor.processId()) + ".json");
    QTRY_VERIFY_WITH_TIMEOUT(QFile::exists(copy) && QFile::exists(about), 120000);
    editor.kill();
    QVERIFY(editor.waitForFinished(10000));
    QCOMPARE(editor.exitStatus(), QProcess::CrashExit);

    // The next start finds the copy and, asked, restores it.
    window_ = makeTestWindow();
    window_->enableAutosave(folder.path(), 3600);
    QString askedAbout;
    window_->confirmRecovery = [&](const RecoveryCopy& c) {
      askedAbout = c.copyPath;
      return true;
    };
    QSignalSpy loaded(window_, &MainWindow::loadFinished);
    QVERIFY(window_->offerRecovery());
    QVERIFY(loaded.wait(120000));
    QCOMPARE(loaded.first().first().toBool(), true);
    QCOMPARE(askedAbout, copy);
    const nlohmann::json& garments = window_->document()->sceneSections().garments;
    QVERIFY2(garments.is_array() && garments.size() == 1 && garments[0].value("name", "") == "Skirt",
             garments.dump().c_str());
    QVERIFY(window_->document()->isModified());
    QVERIFY(window_->document()->documentPath().isEmpty());  // it was never saved: Save asks where
    // The dead editor's copy is gone; this one keeps the changes now.
    QVERIFY(!QFile::exists(copy));
    QVERIFY(QFile::exists(window_->autosave()->copyPath()));
    QVERIFY(Autosave::leftBehind(folder.path()).empty());

    // Saving removes the copy, and so does a clean close after a new edit.
    QVERIFY(window_->saveDocument(folder.filePath("restored.mqscene")));
    QVERIFY(!QFile::exists(window_->autosave()->copyPath()));
    window_->document()->notifyChanged();
    QVERIFY(window_->autosave()->saveNow());
    QVERIFY(QFile::exists(window_->autosave()->copyPath()));
    QVERIFY(window_->close());
    QVERIFY(!QFile::exists(window_->autosave()->copyPath()));
  }

  void declinedRecoveryIsDiscarded() {
    QTemporaryDir folder;
    // A copy from a process that no longer runs (pid 1 is alive; use a
    // number far beyond pid_max).
    QFile stale(folder.filePath("999999999.mqscene"));
    QVERIFY(stale.open(QIODevice::WriteOnly));
    stale.write(R"({"format": "mannequin-scene", "version": 1, "character": "default"})");
    stale.close();
    if (!window_) window_ = makeTestWindow();
    window_->enableAutosave(folder.path(), 3600);
    window_->confirmRecovery = [](const RecoveryCopy&) { return false; };
    QVERIFY(!window_->offerRecovery());
    QVERIFY(!QFile::exists(stale.fileName()));
  }

  void cleanupTestCase() { delete window_; }

 private:
  MainWindow* window_ = nullptr;
};

}  // namespace

int runRecoveryTest(int argc, char** argv) {
  mq::ui::exitAfter(280, "gui_recovery");  // never hang
  RecoveryTest test;
  return QTest::qExec(&test, argc, argv);
}

#include "recovery_test.moc"
