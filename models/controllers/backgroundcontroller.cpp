// BackgroundController: see backgroundcontroller.h.
#include "models/controllers/backgroundcontroller.h"

#include "models/controllers/editcontroller.h"
#include "picture/picture.h"
#include "models/document/commands.h"

#include <QFileInfo>

#include <algorithm>

namespace kontur {

BackgroundController::BackgroundController(EditController *editor)
    : QObject(editor)
    , m_editor(editor)
{
    connect(m_editor->document(), &Document::backgroundChanged, this, &BackgroundController::changed);
}

const Background &BackgroundController::current() const
{
    return m_editor->document()->background();
}

QString BackgroundController::file() const
{
    return current().file;
}

bool BackgroundController::visible() const
{
    return current().visible;
}

double BackgroundController::opacity() const
{
    return current().opacity;
}

void BackgroundController::setBackground(const Background &background)
{
    if (background == current())
        return;
    m_editor->push(new BackgroundCommand(m_editor->document(), current(), background));
}

void BackgroundController::setVisible(bool visible)
{
    Background background = current();
    background.visible = visible;
    setBackground(background);
}

void BackgroundController::setOpacity(double opacity)
{
    Background background = current();
    background.opacity = std::clamp(opacity, 0.0, 1.0);
    setBackground(background);
}

bool BackgroundController::load(const QUrl &file)
{
    const QString path = file.isLocalFile() ? file.toLocalFile() : file.toString();
    const ImageRead image = readImageSize(path);
    if (!image.ok()) {
        Q_EMIT report(Message{Message::FileUploadError, {QFileInfo(path).fileName()}});
        return false;
    }
    Background background;
    background.file = QFileInfo(path).absoluteFilePath();
    background.origin = QPointF(-image.size.width() / 2.0, image.size.height() / 2.0);
    background.scale = 1.0;
    setBackground(background);
    Q_EMIT report({});
    return true;
}

void BackgroundController::clear()
{
    setBackground(Background{});
}

} // namespace kontur
