// The scene files' MIME type as a file manager sees it: the shared MIME
// database is built (update-mime-database) from freedesktop.org's types plus
// resources/io.github.whitted.Whitted.mime.xml into a temporary data directory,
// and Qt's QMimeDatabase, which reads the same cache as file managers, is asked
// what the example scenes and other JSON files are.
#include <QCoreApplication>
#include <QFile>
#include <QMimeDatabase>
#include <QProcess>

#include <filesystem>
#include <string>

#include <gtest/gtest.h>

#include "support/qt_test_main.h"
#include "support/test_support.h"

namespace {

namespace fs = std::filesystem;
const QString kSceneType = QStringLiteral("application/x-whitted-scene");

class SceneMimeTypeTest : public ::testing::Test {
  protected:
    static void SetUpTestSuite() {
        data_ = new whitted::test::TempDir;
        const fs::path packages = data_->path() / "mime" / "packages";
        fs::create_directories(packages);
        fs::copy_file("/usr/share/mime/packages/freedesktop.org.xml",
                      packages / "freedesktop.org.xml");
        fs::copy_file(WHITTED_RESOURCES_DIR "/io.github.whitted.Whitted.mime.xml",
                      packages / "io.github.whitted.Whitted.xml");
        QProcess update;
        update.start(QStringLiteral("update-mime-database"),
                     {QString::fromStdString((data_->path() / "mime").string())});
        ASSERT_TRUE(update.waitForFinished(60000));
        ASSERT_EQ(update.exitCode(), 0) << update.readAllStandardError().toStdString();
        // Before the first QMimeDatabase: Qt reads the directories once.
        qputenv("XDG_DATA_DIRS", QByteArray::fromStdString(data_->path().string()));
        qputenv("XDG_DATA_HOME", QByteArray::fromStdString((data_->path() / "home").string()));
    }
    static void TearDownTestSuite() { delete data_; }

    static QString typeOf(const fs::path& file) {
        return QMimeDatabase().mimeTypeForFile(QString::fromStdString(file.string())).name();
    }

    static whitted::test::TempDir* data_;
};
whitted::test::TempDir* SceneMimeTypeTest::data_ = nullptr;

// By content: what a file manager that sniffs (or a file without the ending) sees.
TEST_F(SceneMimeTypeTest, EveryExampleScene_ByContent_IsAWhittedScene) {
    int scenes = 0;
    for (const auto& entry : fs::recursive_directory_iterator(WHITTED_SCENES_DIR)) {
        if (entry.path().extension() != ".json") continue;
        QFile file(QString::fromStdString(entry.path().string()));
        ASSERT_TRUE(file.open(QIODevice::ReadOnly));
        EXPECT_EQ(QMimeDatabase().mimeTypeForData(file.read(4096)).name().toStdString(),
                  kSceneType.toStdString())
            << entry.path();
        ++scenes;
    }
    EXPECT_GE(scenes, 18);
}

// By name: the ".whitted.json" ending wins over ".json" in every desktop.
TEST_F(SceneMimeTypeTest, WhittedJsonEnding_IsAWhittedScene) {
    whitted::test::TempDir dir;
    const fs::path scene = dir.path() / "my scene.whitted.json";
    fs::copy_file(whitted::test::kSeedScenePath, scene);
    EXPECT_EQ(typeOf(scene).toStdString(), kSceneType.toStdString());
}

TEST_F(SceneMimeTypeTest, OtherJson_StaysJson_AndSceneTypeIsJsonToo) {
    whitted::test::TempDir dir;
    const fs::path other = dir.path() / "package.json";
    whitted::test::writeFile(other, "{\"name\": \"not a scene\", \"version\": \"1.0\"}\n");
    EXPECT_EQ(typeOf(other).toStdString(), "application/json");
    EXPECT_NE(QMimeDatabase().mimeTypeForData(QByteArray("{\"name\": 1}")).name(), kSceneType);
    const QMimeType scene = QMimeDatabase().mimeTypeForName(kSceneType);
    ASSERT_TRUE(scene.isValid());
    EXPECT_TRUE(scene.inherits(QStringLiteral("application/json")));
    EXPECT_EQ(scene.comment(), QStringLiteral("Whitted scene"));
}

TEST_F(SceneMimeTypeTest, DesktopFile_OpensTheSceneType) {
    QFile desktop(WHITTED_RESOURCES_DIR "/io.github.whitted.Whitted.desktop");
    ASSERT_TRUE(desktop.open(QIODevice::ReadOnly));
    const QString text = QString::fromUtf8(desktop.readAll());
    EXPECT_TRUE(text.contains(QStringLiteral("\nMimeType=") + kSceneType + QLatin1Char(';')));
    EXPECT_TRUE(text.contains(QStringLiteral("application/json;")))
        << "scenes named .json are offered to the editor too";
    EXPECT_TRUE(text.contains(QStringLiteral("\nExec=whitted %f\n")));
}

}  // namespace

int main(int argc, char** argv) {
    return whitted::test::runQtTests<QCoreApplication>(argc, argv);
}
