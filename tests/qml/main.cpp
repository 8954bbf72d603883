// QtQuickTest runner for tests/qml/tst_*.qml, with the statically linked Kontur modules.
#include <QQmlEngine>
#include <QtQml/qqmlextensionplugin.h>
#include <QtQuickTest>

Q_IMPORT_QML_PLUGIN(KonturPlugin)
Q_IMPORT_QML_PLUGIN(Kontur_ModelsPlugin)

class Setup final : public QObject
{
    Q_OBJECT
public Q_SLOTS:
    void qmlEngineAvailable(QQmlEngine *engine)
    {
        // Qt >= 6.5 has qrc:/qt/qml on the import path already.
        engine->addImportPath(QStringLiteral("qrc:/qt/qml"));
    }
};

QUICK_TEST_MAIN_WITH_SETUP(kontur_qml, Setup)
#include "main.moc"
