// Image size controls: the common sizes (one table, for the Render tab and the
// Export dialog), and the Export dialog's width and height kept to the scene's
// aspect ratio unless the user unlocks them, because another aspect frames
// the picture differently from what the view showed.
#pragma once

#include <QString>
#include <QWidget>

#include <vector>

class QComboBox;
class QLabel;
class QSpinBox;
class QCheckBox;

namespace whitted::ui {

class SceneDocument;

struct CommonSize {
    const char* name;  // "HD 720p"
    int width, height;
};
// HD, Full HD, 4K, VGA, square and portrait sizes, in the order menus list them.
const std::vector<CommonSize>& commonSizes();
// "1920 × 1080 (16:9)"
QString sizeText(int width, int height);

// For the Render tab: a combo box that sets the scene's width and height to a
// common size as one undo step, so the view frames what will be exported.
// Object name "renderCommonSize".
QComboBox* makeCommonSizeChooser(SceneDocument* doc, QWidget* parent = nullptr);

// Width and height with an aspect lock, a common-size menu and a note that
// says when the framing will differ from the scene's. Spin boxes named
// `<prefix>Width` and `<prefix>Height`, the lock `<prefix>AspectLock`, the
// combo `<prefix>CommonSize`, the note `<prefix>AspectNote`.
class ImageSizeFields : public QWidget {
    Q_OBJECT
  public:
    ImageSizeFields(int sceneWidth, int sceneHeight, const QString& prefix,
                    QWidget* parent = nullptr);
    int imageWidth() const;
    int imageHeight() const;
    bool aspectLocked() const;

  private:
    void widthChanged(int width);
    void heightChanged(int height);
    void commonSizeChosen(int index);
    void updateNote();

    double sceneAspect_;
    QSpinBox* width_;
    QSpinBox* height_;
    QCheckBox* lock_;
    QComboBox* common_;
    QLabel* note_;
};

}  // namespace whitted::ui
