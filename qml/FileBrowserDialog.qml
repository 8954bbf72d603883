// FileBrowserDialog: Kontur's own file dialog, made for a finger as much as for a mouse and a keyboard
// (Qt 6.4's QtQuick.Dialogs FileDialog shows a typed path only after Ctrl+L and opens a folder only on
// a double tap). A path field that goes where a typed path says, Up and the folder's parents as
// breadcrumbs, folders first and then the files that match the chosen name filter in rows a finger
// hits; one tap opens a folder or picks a file, a second tap on it (or Open / Save, or Enter)
// accepts. In save mode a name field starts with the suggested name, the format's extension is
// appended as DocumentFiles appends it, and an existing file is replaced only after a question.
// The API is the part of FileDialog's that Kontur uses: currentFolder, selectedFile, nameFilters,
// defaultSuffix, fileMode, acceptLabel, title, open(), accepted() and rejected(). The path rules are
// C++ (models/controllers/filepaths.h); its content (FileBrowserPage) is made while it shows, anew each time.
pragma ComponentBehavior: Bound
import QtQuick
import QtQuick.Controls
import QtQuick.Controls.Material
import QtQuick.Layouts
import Kontur
import Kontur.Models

Dialog {
    id: dialog

    // The values of QtQuick.Dialogs' FileDialog.OpenFile and FileDialog.SaveFile.
    enum FileMode { OpenFile = 0, SaveFile = 2 }
    // What the message under the path says; kept as a kind and a path (not as text) so that it
    // follows a language switch.
    enum Problem { None, NoSuchPath, Unreadable, NoName }

    property int fileMode: FileBrowserDialog.OpenFile
    property url currentFolder
    // The answer once accepted; in save mode, set before open(), the name the field starts with.
    property url selectedFile
    // "Images (*.png *.jpg)": a chooser shows when there are several.
    property var nameFilters: []
    property int selectedNameFilterIndex: 0
    // Appended to a name saved without it ("dxf", no dot), as DocumentFiles does.
    property string defaultSuffix
    // False where saving adds to the file rather than replacing it (Append to a points file).
    property bool confirmOverwrite: true
    property string acceptLabel: saveMode ? qsTr("Save") : qsTr("Open")

    readonly property bool saveMode: fileMode === FileBrowserDialog.SaveFile
    property int problem: FileBrowserDialog.Problem.None
    property string problemPath
    // The file picked by a tap in the list (a url's text; empty when none).
    property string picked

    // The folder `url` (a folder known to exist), unless it cannot be listed.
    function openFolder(url) {
        const found = FilePaths.resolve(FilePaths.displayPath(url), url)
        if (found.kind === FilePaths.Unreadable) {
            showProblem(FileBrowserDialog.Problem.Unreadable, found.path)
            return
        }
        problem = FileBrowserDialog.Problem.None
        picked = ""
        currentFolder = url
        if (content.item) // also where the folder is the one shown, and a path to it was typed
            content.item.pathText = FilePaths.displayPath(url)
    }
    // A path typed into the path field: a folder is opened, a file picked and accepted, a new file's
    // name in an existing folder taken as the name to save; anything else is said, and nothing typed
    // or chosen is lost.
    function goToTyped(text) {
        const found = FilePaths.resolve(text, currentFolder)
        switch (found.kind) {
        case FilePaths.Folder:
            openFolder(found.url)
            return
        case FilePaths.Unreadable:
            showProblem(FileBrowserDialog.Problem.Unreadable, found.path)
            return
        case FilePaths.File:
            openFolder(found.folder)
            pick(found.url, FilePaths.fileName(found.url))
            tryAccept()
            return
        case FilePaths.NewFile:
            if (saveMode) {
                openFolder(found.folder)
                pick("", FilePaths.fileName(found.url))
                tryAccept()
                return
            }
            break
        }
        showProblem(FileBrowserDialog.Problem.NoSuchPath, found.path)
    }
    function showProblem(kind, path) {
        problemPath = path
        problem = kind
    }
    // A file picked: remembered, and in save mode its name put into the name field.
    function pick(url, name) {
        picked = url.toString()
        if (saveMode && content.item)
            content.item.fileName = name
    }
    // Open, Save, Enter or a second tap: the picked or typed file, after the question whether to
    // replace it where that applies.
    function tryAccept() {
        const page = content.item
        if (!page)
            return
        if (!saveMode) {
            if (picked.length > 0)
                finish(picked)
            else if (page.pathEdited)
                goToTyped(page.pathText)
            return
        }
        const typed = page.fileName.trim()
        if (typed.length === 0) {
            showProblem(FileBrowserDialog.Problem.NoName, "")
            return
        }
        const found = FilePaths.resolve(typed, currentFolder)
        if (found.kind === FilePaths.Folder || found.kind === FilePaths.Unreadable) {
            openFolder(found.url) // a folder's name typed: into it, the name to be typed there
            return
        }
        if (found.kind === FilePaths.Missing) {
            showProblem(FileBrowserDialog.Problem.NoSuchPath, found.path)
            return
        }
        const target = FilePaths.saveTarget(typed, currentFolder, defaultSuffix)
        if (confirmOverwrite && FilePaths.exists(target)) {
            page.askOverwrite(target)
            return
        }
        finish(target)
    }
    function finish(url) {
        selectedFile = url
        accept()
    }

    parent: Overlay.overlay
    anchors.centerIn: parent
    width: parent ? Math.min(parent.width - 2 * Theme.spacing, Math.max(760, parent.width * 0.5)) : 760
    height: parent ? Math.min(parent.height - 2 * Theme.spacing, 1000) : 600
    modal: true
    // Over the docked side panel (a drawer, opened again after a language switch or a resize).
    z: 1
    // Not closed by a stray tap beside it: what was typed stays.
    closePolicy: Popup.CloseOnEscape
    padding: 2 * Theme.spacing
    topPadding: Theme.spacing
    Material.elevation: parent && parent.GraphicsInfo.api === GraphicsInfo.Software ? 0 : 24
    focus: true
    onAboutToShow: {
        if (!FilePaths.exists(currentFolder))
            currentFolder = FilePaths.homeFolder()
        problem = FileBrowserDialog.Problem.None
        picked = ""
        content.setSource("FileBrowserPage.qml", {dialog: dialog})
    }
    onClosed: content.source = ""
    onOpened: if (content.item) content.item.takeFocus()

    // Made while the dialog shows: eleven dialogs made with the window would slow its start.
    contentItem: Loader {
        id: content
        focus: true
    }
}
