// FileActions: the file commands as actions of the registry (AppActions; shared by the File menu,
// the overflow menu and the keyboard), their file dialogs (Kontur's own FileBrowserDialog), and the
// question before losing unsaved changes: each command that would replace the document asks first
// (save, don't save, cancel), and goes on once the answer allows it. The work itself (paths, formats, the PNG picture, messages)
// is C++'s: DocumentFiles (the document's file), Exporter, Recovery and RecentFiles.
pragma ComponentBehavior: Bound
import QtQuick
import QtQuick.Controls
import Kontur
import Kontur.Models

Item {
    id: fileActions

    required property EditController editor
    required property DocumentFiles files
    required property Exporter exporter
    required property Recovery recovery
    required property RecentFiles recent
    required property CurveCanvas canvas

    // What to do once the user has answered the unsaved-changes question.
    property var afterUnsaved: null
    property bool closeConfirmed: false
    // Resolution of the next PNG export, as a multiple of the view's size, and whether it shows
    // every curve (the canvas fits them for the picture and puts the view back afterwards).
    property real pngScale: 2
    property bool pngWholeDocument: false
    // Whether the next DXF export flattens the curves into polylines (else exact splines).
    property bool dxfPolylines: false

    readonly property alias newAction: newAction
    readonly property alias openAction: openAction
    readonly property alias saveAction: saveAction
    readonly property alias saveAsAction: saveAsAction
    readonly property alias importAction: importAction
    readonly property alias exportSvgAction: exportSvgAction
    readonly property alias exportDxfAction: exportDxfAction
    readonly property alias exportDxfPolylineAction: exportDxfPolylineAction
    readonly property alias exportAamaAction: exportAamaAction
    readonly property alias exportCsvAction: exportCsvAction
    readonly property alias appendAction: appendAction
    readonly property alias printAction: printAction
    readonly property alias printer: printer

    // Runs `action` at once, or after the user saved or discarded the unsaved changes.
    function askUnsaved(action) {
        if (!editor.modified) {
            action()
            return
        }
        afterUnsaved = action
        unsavedDialog.open()
    }
    function saveThen(action) {
        if (files.save()) {
            action()
            return
        }
        afterUnsaved = action
        openSaveDialog(saveDialog)
    }
    // A save or export dialog, opened on the name DocumentFiles suggests for its format (the
    // document's name with the format's extension): every time anew, so that nothing typed the
    // last time stays in the field. DocumentFiles also decides the path its answer is written to
    // (the dialog appends the extension by the same rule, so that it asks about the file written).
    function openSaveDialog(dialog) {
        dialog.currentFolder = files.startFolder()
        dialog.selectedFile = files.suggestedFile(dialog.defaultSuffix)
        dialog.open()
    }
    // An open dialog, in the folder DocumentFiles chooses (the document's or the last one used).
    function openFileDialog(dialog) {
        dialog.currentFolder = files.startFolder()
        dialog.open()
    }
    function takeAfterUnsaved() {
        const action = afterUnsaved
        afterUnsaved = null
        return action
    }
    // The document given on the command line, and the recovery question after a crash (with a
    // document given too: the unsaved work of the crashed instance is offered all the same).
    function start(startupFile) {
        if (startupFile.toString().length > 0)
            files.open(startupFile)
        if (recovery.hasRecovery)
            recoveryDialog.open()
    }
    // The window is closing: with unsaved changes, ask first and close again once answered.
    function closing(close) {
        if (editor.modified && !closeConfirmed) {
            close.accepted = false
            askUnsaved(() => {
                fileActions.closeConfirmed = true
                fileActions.Window.window.close()
            })
            return
        }
        recovery.closing()
    }
    // A file dropped or picked from the recent list: a document opens, anything else is imported.
    function openDropped(url) {
        const name = url.toString().toLowerCase()
        if (name.endsWith(".kontur") || name.endsWith(".pdf"))
            askUnsaved(() => files.open(url))
        else
            withUnits(url, () => files.importFile(url, CurveKind.Composite))
    }
    // Runs `action` at once, or after the user said which units `url` is in (a file that does not
    // say, asked once per kind of file: DocumentFiles remembers the answer).
    function withUnits(url, action) {
        if (!files.needsUnits(url)) {
            action()
            return
        }
        unitsDialog.url = url
        unitsDialog.action = action
        unitsDialog.changing = false
        unitsDialog.current = "mm"
        unitsDialog.fileName = decodeURIComponent(url.toString().split("/").pop())
        unitsDialog.open()
    }
    // The message's offer after a DXF was read in the remembered units: choose others
    // (DocumentFiles reads the file again in them while nothing was done since).
    function changeUnitlessUnits() {
        unitsDialog.action = null
        unitsDialog.changing = true
        unitsDialog.current = files.dxfUnitlessUnits
        unitsDialog.open()
    }
    function openRecent(path) {
        const url = "file://" + path
        askUnsaved(() => withUnits(url, () => files.open(url)))
    }
    function exportPng(scale, wholeDocument) {
        pngScale = scale
        pngWholeDocument = wholeDocument
        openSaveDialog(pngDialog)
    }
    function loadBackground() {
        openFileDialog(backgroundDialog)
    }

    KonturAction {
        id: newAction
        objectName: "newAction"
        iconName: "document-new-symbolic"
        //: Command (verb/adjective): start a new, empty document.
        text: qsTr("New")
        shortcut: StandardKey.New
        onTriggered: fileActions.askUnsaved(() => fileActions.files.newDocument())
    }
    KonturAction {
        id: openAction
        objectName: "openAction"
        iconName: "document-open-symbolic"
        text: qsTr("Open…")
        shortcut: StandardKey.Open
        onTriggered: fileActions.askUnsaved(() => fileActions.openFileDialog(openDialog))
    }
    KonturAction {
        id: saveAction
        objectName: "saveAction"
        iconName: "document-save-symbolic"
        text: qsTr("Save")
        shortcut: StandardKey.Save
        onTriggered: fileActions.saveThen(() => {})
    }
    KonturAction {
        id: saveAsAction
        objectName: "saveAsAction"
        iconName: "document-save-as-symbolic"
        text: qsTr("Save as…")
        onTriggered: {
            fileActions.afterUnsaved = null
            fileActions.openSaveDialog(saveDialog)
        }
    }
    KonturAction {
        id: importAction
        objectName: "importAction"
        iconName: "kontur-import"
        text: qsTr("Import points, CSV, SVG or DXF…")
        onTriggered: fileActions.openFileDialog(importDialog)
    }
    KonturAction {
        id: exportSvgAction
        objectName: "exportSvgAction"
        iconName: "kontur-export"
        text: qsTr("Export SVG…")
        onTriggered: fileActions.openSaveDialog(svgDialog)
    }
    KonturAction {
        id: exportDxfAction
        objectName: "exportDxfAction"
        iconName: "kontur-export"
        text: qsTr("Export DXF with splines…")
        toolTip: qsTr("The exact curves as DXF splines, in the document's units, for CAD and pattern software")
        onTriggered: {
            fileActions.dxfPolylines = false
            fileActions.openSaveDialog(dxfDialog)
        }
    }
    KonturAction {
        id: exportDxfPolylineAction
        objectName: "exportDxfPolylineAction"
        iconName: "kontur-export"
        text: qsTr("Export DXF with polylines…")
        toolTip: qsTr("The curves as DXF polylines within 0.05 mm, for plotters and cutters without splines")
        onTriggered: {
            fileActions.dxfPolylines = true
            fileActions.openSaveDialog(dxfDialog)
        }
    }
    KonturAction {
        id: exportAamaAction
        objectName: "exportAamaAction"
        iconName: "kontur-export"
        //: AAMA (ASTM D6673) is the DXF that garment pattern software and cutters exchange pieces in.
        text: qsTr("Export DXF for pattern software (AAMA)…")
        toolTip: qsTr("Each closed curve as a pattern piece (ASTM D6673): its seam allowance as the cut line, "
                      + "the curve as the sew line, polylines within 0.05 mm")
        // Without a closed curve Exporter says so and no file name is asked for.
        onTriggered: {
            if (fileActions.exporter.hasPieces())
                fileActions.openSaveDialog(aamaDialog)
        }
    }
    KonturAction {
        id: exportCsvAction
        objectName: "exportCsvAction"
        iconName: "kontur-table-export"
        text: qsTr("Export the selected curve as CSV…")
        enabled: fileActions.editor.selection.hasCurve
        onTriggered: fileActions.openSaveDialog(csvDialog)
    }
    KonturAction {
        id: appendAction
        objectName: "appendAction"
        iconName: "kontur-append"
        text: qsTr("Append the selected curve to a points file…")
        enabled: fileActions.editor.selection.hasCurve
        onTriggered: fileActions.openSaveDialog(appendDialog)
    }

    KonturAction {
        id: printAction
        objectName: "printAction"
        iconName: "document-print-symbolic"
        text: qsTr("Print pattern…")
        shortcut: StandardKey.Print
        onTriggered: printDialog.open()
    }
    // The print dialog's choices, its page count and the PDF (models/controllers/printcontroller.h).
    PrintController {
        id: printer
        objectName: "printer"
        editor: fileActions.editor
    }
    PrintDialog {
        id: printDialog
        printer: printer
        onPrintRequested: fileActions.openSaveDialog(pdfDialog)
    }
    FileBrowserDialog {
        id: pdfDialog
        acceptLabel: qsTr("Save")
        objectName: "pdfDialog"
        title: qsTr("Print pattern to PDF")
        fileMode: FileBrowserDialog.SaveFile
        defaultSuffix: "pdf"
        nameFilters: [qsTr("PDF files (*.pdf)")]
        onAccepted: printer.print(selectedFile)
    }

    // The suffixes come from the one table of formats (io/formats.h), through DocumentFiles.
    readonly property var documentFilters: [
        qsTr("Kontur documents and printed patterns (%1)").arg(files.filePatterns(true)),
        qsTr("Points, CSV, SVG and DXF files (%1)").arg(files.filePatterns(false)), qsTr("All files (*)")]
    FileBrowserDialog {
        id: openDialog
        objectName: "openDialog"
        //: Title of the file dialog that opens a document (verb: open a file).
        title: qsTr("Open")
        nameFilters: fileActions.documentFilters
        onAccepted: fileActions.withUnits(selectedFile, () => fileActions.files.open(selectedFile))
    }
    FileBrowserDialog {
        id: saveDialog
        objectName: "saveDialog"
        acceptLabel: qsTr("Save")
        title: qsTr("Save as")
        fileMode: FileBrowserDialog.SaveFile
        defaultSuffix: "kontur"
        nameFilters: [qsTr("Kontur documents (*.kontur)")]
        onAccepted: {
            if (fileActions.files.saveAs(selectedFile) && fileActions.afterUnsaved)
                fileActions.takeAfterUnsaved()()
        }
    }
    FileBrowserDialog {
        id: importDialog
        objectName: "importDialog"
        title: qsTr("Import")
        nameFilters: [qsTr("Points, CSV, SVG, DXF, Kontur files and printed patterns (%1)")
            .arg(fileActions.files.filePatterns(false) + " " + fileActions.files.filePatterns(true)), qsTr("All files (*)")]
        onAccepted: fileActions.withUnits(selectedFile, () => fileActions.files.importFile(selectedFile,
                                                 fileActions.editor.placement.kind === CurveKind.Bezier
                                                 ? CurveKind.Composite : fileActions.editor.placement.kind))
    }
    FileBrowserDialog {
        id: svgDialog
        objectName: "svgDialog"
        acceptLabel: qsTr("Export")
        title: qsTr("Export SVG")
        fileMode: FileBrowserDialog.SaveFile
        defaultSuffix: "svg"
        nameFilters: [qsTr("SVG images (*.svg)")]
        onAccepted: fileActions.exporter.exportSvg(selectedFile)
    }
    FileBrowserDialog {
        id: dxfDialog
        objectName: "dxfDialog"
        acceptLabel: qsTr("Export")
        title: qsTr("Export DXF")
        fileMode: FileBrowserDialog.SaveFile
        defaultSuffix: "dxf"
        nameFilters: [qsTr("DXF drawings (*.dxf)")]
        onAccepted: fileActions.exporter.exportDxf(selectedFile, fileActions.dxfPolylines)
    }
    FileBrowserDialog {
        id: aamaDialog
        objectName: "aamaDialog"
        acceptLabel: qsTr("Export")
        title: qsTr("Export DXF for pattern software")
        fileMode: FileBrowserDialog.SaveFile
        defaultSuffix: "dxf"
        nameFilters: [qsTr("DXF drawings (*.dxf)")]
        onAccepted: fileActions.exporter.exportAamaDxf(selectedFile)
    }
    FileBrowserDialog {
        id: csvDialog
        objectName: "csvDialog"
        acceptLabel: qsTr("Export")
        title: qsTr("Export CSV")
        fileMode: FileBrowserDialog.SaveFile
        defaultSuffix: "csv"
        nameFilters: [qsTr("CSV files (*.csv)")]
        onAccepted: fileActions.exporter.exportCsv(selectedFile)
    }
    FileBrowserDialog {
        id: appendDialog
        objectName: "appendDialog"
        acceptLabel: qsTr("Append")
        title: qsTr("Append to a points file")
        fileMode: FileBrowserDialog.SaveFile
        defaultSuffix: "txt"
        confirmOverwrite: false // it appends, it never overwrites
        nameFilters: [qsTr("Points files (*.txt)")]
        onAccepted: fileActions.exporter.appendPoints(selectedFile)
    }
    FileBrowserDialog {
        id: pngDialog
        objectName: "pngDialog"
        acceptLabel: qsTr("Export")
        title: qsTr("Export PNG")
        fileMode: FileBrowserDialog.SaveFile
        defaultSuffix: "png"
        nameFilters: [qsTr("PNG images (*.png)")]
        onAccepted: fileActions.exporter.exportPng(fileActions.canvas, selectedFile, fileActions.pngScale,
                                                fileActions.pngWholeDocument)
    }
    FileBrowserDialog {
        id: backgroundDialog
        objectName: "backgroundDialog"
        title: qsTr("Load background image")
        nameFilters: [qsTr("Images (*.png *.jpg *.jpeg *.heic *.heif *.bmp *.gif *.webp)"), qsTr("All files (*)")]
        onAccepted: {
            fileActions.files.rememberFolder(selectedFile)
            fileActions.editor.background.load(selectedFile)
        }
    }

    UnitsDialog {
        id: unitsDialog
        objectName: "unitsDialog"
        property url url
        property var action: null
        onChosen: units => {
            if (changing) {
                fileActions.files.changeUnitlessUnits(units)
                return
            }
            fileActions.files.rememberUnits(url, units)
            if (action)
                action()
            action = null
        }
    }
    ConfirmDialog {
        id: unsavedDialog
        objectName: "unsavedDialog"
        title: qsTr("Unsaved changes")
        text: qsTr("“%1” has changes that are not saved. Save them first?").arg(fileActions.files.displayName)
        acceptText: qsTr("Save")
        discardText: qsTr("Don’t save")
        rejectText: qsTr("Cancel")
        onAccepted: fileActions.saveThen(fileActions.takeAfterUnsaved() ?? (() => {}))
        onDiscarded: {
            const action = fileActions.takeAfterUnsaved()
            fileActions.editor.markSaved()
            if (action)
                action()
        }
        onRejected: fileActions.afterUnsaved = null
    }
    ConfirmDialog {
        id: recoveryDialog
        objectName: "recoveryDialog"
        title: qsTr("Recover unsaved work")
        text: qsTr("Kontur was not closed properly last time. Recover the unsaved work?")
        acceptText: qsTr("Recover")
        discardText: qsTr("Discard")
        rejectText: ""
        onAccepted: fileActions.recovery.recover()
        // Several instances may have crashed: each copy is asked about in turn (a recovered one
        // becomes the document; those left are asked about at the next start).
        onDiscarded: {
            fileActions.recovery.discardRecovery()
            if (fileActions.recovery.hasRecovery)
                Qt.callLater(recoveryDialog.open)
        }
    }
}
