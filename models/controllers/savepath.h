// Where a save or export goes: the file a save dialog's answer names, with the format's extension, and
// the name a save dialog suggests first. Pure decisions on paths (no file is touched), so that they are
// tested without a window.
#pragma once

#include <QString>
#include <QUrl>

namespace kontur {

// The local file to write for a save dialog's answer `file` in the format whose extension is
// `extension` ("dxf", no dot); empty when it names no file (no name typed, a URL that is not local).
// - A file: URL is its local path; a URL without a scheme is taken as a path, as Qt 6.4's own file
//   dialog makes one from its folder and the name typed (QUrl(folder + "/" + name)).
// - A name typed as an absolute path or as a file: URL is not joined to the dialog's folder:
//   "/home/a//tmp/x.dxf" is "/tmp/x.dxf", "/home/a/file:///tmp/x.dxf" is "/tmp/x.dxf".
// - A relative path is taken from `baseFolder`.
// - The extension is enforced by appending it when the name does not end in it (case aside):
//   "a.svg" exported as DXF is "a.svg.dxf". Appending rather than replacing keeps what was typed
//   visible and never overwrites the "a.svg" the name pointed at with a drawing of another format;
//   a DXF is never written under .svg, where no reader would take it.
[[nodiscard]] QString savePathFor(const QUrl &file, const QString &extension, const QString &baseFolder = {});

// The name a save dialog suggests: the document's name (`documentFile`, empty when unsaved: then
// `untitled`) with `extension`; "bodice.kontur" exported as DXF suggests "bodice.dxf".
[[nodiscard]] QString suggestedFileName(const QUrl &documentFile, const QString &extension, const QString &untitled);

} // namespace kontur
