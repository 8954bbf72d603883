// FileBrowserPage: what FileBrowserDialog shows, made each time it opens (and so anew): the path
// field with Up and Go, the breadcrumbs, the message, the list of folders and files, the filter
// chooser, the name field in save mode, Cancel and Open / Save, and the question before replacing a
// file. What it does is the dialog's; this page only shows and asks.
pragma ComponentBehavior: Bound
import QtQuick
import QtQuick.Controls
import QtQuick.Controls.Material
import QtQuick.Layouts
import Qt.labs.folderlistmodel
import Kontur
import Kontur.Models

ColumnLayout {
    id: column

    required property FileBrowserDialog dialog
    objectName: "fileBrowserContent"
    spacing: Theme.spacing
    focus: true

    property alias fileName: nameField.text
    property alias pathText: pathField.text
    readonly property bool pathEdited: pathField.text !== FilePaths.displayPath(column.dialog.currentFolder)
    function askOverwrite(target) {
        overwriteDialog.target = target
        overwriteDialog.open()
    }

    // Whether the name was typed into (then nothing selects it again).
    property bool nameEdited: false

    Component.onCompleted: {
        pathField.text = FilePaths.displayPath(column.dialog.currentFolder)
        if (column.dialog.saveMode)
            nameField.text = FilePaths.fileName(column.dialog.selectedFile)
        takeFocus()
    }
    // In save mode the name field, as in every desktop's save dialog; else the list. Called as the
    // page is made and again once the dialog has opened (the popup takes the focus then), without
    // undoing what was typed in between.
    function takeFocus() {
        if (column.dialog.saveMode) {
            if (!nameField.activeFocus && !pathField.activeFocus)
                nameField.forceActiveFocus()
            if (!nameEdited && nameField.activeFocus && nameField.selectedText.length === 0) {
                // The name without its extension selected: typing replaces it, Enter saves it. A
                // selection already made (Ctrl+A before the dialog had opened) stays.
                const dot = nameField.text.lastIndexOf(".")
                nameField.select(0, dot > 0 ? dot : nameField.text.length)
            }
        } else if (!pathField.activeFocus) {
            list.forceActiveFocus()
        }
    }
    Connections {
        target: column.dialog
        function onCurrentFolderChanged() {
            pathField.text = FilePaths.displayPath(column.dialog.currentFolder)
            list.currentIndex = -1
            list.positionViewAtBeginning()
        }
    }

    // Up, the path field, Go.
    RowLayout {
        Layout.fillWidth: true
        spacing: Theme.spacing / 2
        ToolButton {
            objectName: "fileDialogUp"
            icon.source: "icons/go-up-symbolic.svg"
            enabled: FilePaths.parentFolder(column.dialog.currentFolder).toString().length > 0
            Layout.preferredWidth: Theme.touchMinimum
            Layout.preferredHeight: Theme.touchMinimum
            //: File dialog: go to the folder that contains this one.
            Accessible.name: qsTr("Up one folder")
            ToolTip.visible: hovered
            ToolTip.text: Accessible.name
            onClicked: column.dialog.openFolder(FilePaths.parentFolder(column.dialog.currentFolder))
        }
        TextField {
            id: pathField
            objectName: "fileDialogPath"
            Layout.fillWidth: true
            Layout.minimumHeight: Theme.touchMinimum
            inputMethodHints: Qt.ImhNoAutoUppercase | Qt.ImhNoPredictiveText
            selectByMouse: true
            //: File dialog: the field that shows the folder's path and takes a typed one.
            Accessible.name: qsTr("Folder or file path")
            placeholderText: Accessible.name
            onAccepted: column.dialog.goToTyped(text)
        }
        Button {
            objectName: "fileDialogGo"
            flat: true
            //: File dialog: go to the folder or file typed into the path field.
            text: qsTr("Go")
            Accessible.name: text
            Layout.minimumHeight: Theme.touchMinimum
            Layout.minimumWidth: Theme.touchMinimum
            onClicked: column.dialog.goToTyped(pathField.text)
        }
    }
    // The folder's parents, each a tap away; the last one is the folder shown.
    ListView {
        id: crumbs
        objectName: "fileDialogCrumbs"
        Layout.fillWidth: true
        Layout.preferredHeight: Theme.touchMinimum
        orientation: ListView.Horizontal
        clip: true
        boundsBehavior: Flickable.StopAtBounds
        model: FilePaths.crumbs(column.dialog.currentFolder)
        onCountChanged: Qt.callLater(crumbs.positionViewAtEnd)
        onWidthChanged: Qt.callLater(crumbs.positionViewAtEnd)
        delegate: Row {
            id: crumb
            required property var modelData
            required property int index
            height: crumbs.height
            Label {
                visible: crumb.index > 1
                text: "/"
                color: Theme.mutedText
                anchors.verticalCenter: parent.verticalCenter
            }
            Button {
                objectName: "fileDialogCrumb" + crumb.index
                flat: true
                text: crumb.modelData.name
                font.bold: crumb.index === crumbs.count - 1
                // Folder names as they are written (the style's buttons would capitalise them).
                font.capitalization: Font.MixedCase
                implicitWidth: Math.max(Theme.touchMinimum, implicitContentWidth + leftPadding + rightPadding)
                height: crumbs.height
                topInset: 0
                bottomInset: 0
                leftPadding: Theme.spacing
                rightPadding: Theme.spacing
                Accessible.name: text
                onClicked: column.dialog.openFolder(crumb.modelData.url)
            }
        }
    }
    Label {
        objectName: "fileDialogMessage"
        Layout.fillWidth: true
        visible: column.dialog.problem !== FileBrowserDialog.Problem.None
        wrapMode: Text.Wrap
        color: Theme.errorText
        text: column.dialog.problem === FileBrowserDialog.Problem.NoSuchPath
              ? qsTr("There is no folder or file “%1”.").arg(column.dialog.problemPath)
              : column.dialog.problem === FileBrowserDialog.Problem.Unreadable
                ? qsTr("The folder “%1” cannot be read.").arg(column.dialog.problemPath)
                : column.dialog.problem === FileBrowserDialog.Problem.NoName
                  ? qsTr("Type a name for the file.") : ""
    }
    // Folders first, then the files the filter lets through.
    ListView {
        id: list
        objectName: "fileDialogList"
        Layout.fillWidth: true
        Layout.fillHeight: true
        clip: true
        boundsBehavior: Flickable.StopAtBounds
        keyNavigationEnabled: true
        currentIndex: -1
        ScrollBar.vertical: ScrollBar {}
        model: FolderListModel {
            id: folderModel
            folder: column.dialog.currentFolder
            nameFilters: FilePaths.patterns(column.dialog.nameFilters.length > 0
                                            ? column.dialog.nameFilters[Math.min(column.dialog.selectedNameFilterIndex,
                                                                          column.dialog.nameFilters.length - 1)]
                                            : "*")
            showDirsFirst: true
            showDotAndDotDot: false
            showHidden: false
            caseSensitive: false
            sortCaseSensitive: false
        }
        Keys.onReturnPressed: list.enterCurrent()
        Keys.onEnterPressed: list.enterCurrent()
        // Enter on the row the arrow keys chose: a folder is opened, a file taken.
        function enterCurrent() {
            const row = list.currentItem
            if (!row) {
                column.dialog.tryAccept()
            } else if (row.fileIsDir) {
                column.dialog.openFolder(row.fileUrl)
            } else {
                column.dialog.pick(row.fileUrl, row.fileName)
                column.dialog.tryAccept()
            }
        }
        delegate: ItemDelegate {
            id: row
            required property string fileName
            required property url fileUrl
            required property bool fileIsDir
            required property int index
            objectName: "fileDialogRow_" + fileName
            width: ListView.view.width
            implicitHeight: Math.max(Theme.touchMinimum, implicitContentHeight + topPadding + bottomPadding)
            text: fileName
            icon.source: fileIsDir ? "icons/folder-symbolic.svg" : "icons/text-x-generic-symbolic.svg"
            highlighted: !fileIsDir && column.dialog.picked === fileUrl.toString()
            Accessible.name: fileName
            onClicked: {
                list.currentIndex = index
                if (fileIsDir)
                    column.dialog.openFolder(fileUrl)
                else if (column.dialog.picked === fileUrl.toString())
                    column.dialog.tryAccept()
                else
                    column.dialog.pick(fileUrl, fileName)
            }
        }
        Label {
            anchors.centerIn: parent
            width: parent.width - 4 * Theme.spacing
            horizontalAlignment: Text.AlignHCenter
            wrapMode: Text.Wrap
            visible: list.count === 0 && folderModel.status === FolderListModel.Ready
            color: Theme.mutedText
            //: File dialog: the folder shown has no subfolder and no file that the filter lets through.
            text: qsTr("No folders and no matching files here.")
        }
    }
    ComboBox {
        objectName: "fileDialogFilter"
        Layout.fillWidth: true
        Layout.minimumHeight: Theme.touchMinimum
        visible: column.dialog.nameFilters.length > 1
        model: column.dialog.nameFilters
        currentIndex: column.dialog.selectedNameFilterIndex
        //: File dialog: which kinds of files the list shows.
        Accessible.name: qsTr("Files of type")
        onActivated: index => column.dialog.selectedNameFilterIndex = index
    }
    RowLayout {
        Layout.fillWidth: true
        visible: column.dialog.saveMode
        spacing: Theme.spacing
        Label {
            //: File dialog: the name of the file to save.
            text: qsTr("Name")
        }
        TextField {
            id: nameField
            objectName: "fileDialogName"
            Layout.fillWidth: true
            Layout.minimumHeight: Theme.touchMinimum
            inputMethodHints: Qt.ImhNoAutoUppercase | Qt.ImhNoPredictiveText
            selectByMouse: true
            Accessible.name: qsTr("File name")
            onTextEdited: {
                column.dialog.picked = ""
                column.nameEdited = true
            }
            onAccepted: column.dialog.tryAccept()
        }
    }
    RowLayout {
        Layout.fillWidth: true
        spacing: Theme.spacing
        Item {
            Layout.fillWidth: true
        }
        Button {
            objectName: "fileDialogCancel"
            text: qsTr("Cancel")
            flat: true
            Accessible.name: text
            Layout.minimumHeight: Theme.touchMinimum
            onClicked: column.dialog.reject()
        }
        Button {
            objectName: "fileDialogAccept"
            text: column.dialog.acceptLabel
            // Flat: a raised button's shadow is a layer effect that the software backend does not draw,
            // and the button's background and white text vanish with it.
            flat: true
            highlighted: true
            Accessible.name: text
            Layout.minimumHeight: Theme.touchMinimum
            enabled: column.dialog.saveMode ? nameField.text.trim().length > 0
                                     : column.dialog.picked.length > 0 || column.pathEdited
            onClicked: column.dialog.tryAccept()
        }
    }

    ConfirmDialog {
        id: overwriteDialog
        objectName: "fileDialogOverwrite"
        z: column.dialog.z + 1 // over the file dialog
        property url target
        title: qsTr("Replace the file?")
        text: qsTr("“%1” already exists. Replace it?").arg(FilePaths.displayPath(target))
        acceptText: qsTr("Replace")
        rejectText: qsTr("Cancel")
        onAccepted: column.dialog.finish(target)
    }
}
