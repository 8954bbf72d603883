// The translations keep the glossary (issue 20): for each term of i18n/glossary.tsv, every message
// whose English source uses the term uses the glossary's translation, by stem so that inflected
// forms count, in all four languages. Reports every miss at once (language, context, source and
// translation), so that one run shows all there is to fix.
#include <QFile>
#include <QRegularExpression>
#include <QXmlStreamReader>
#include <QtTest>

namespace {

const QStringList kLanguages{QStringLiteral("lv"), QStringLiteral("sk"), QStringLiteral("bg"), QStringLiteral("ru")};

struct Term
{
    QRegularExpression pattern;
    QStringList stems[4]; // per language, in lower case
    QStringList skipContexts;
};

struct Message
{
    QString context;
    QString source;
    QStringList translations; // one, or the plural forms
};

QList<Term> readGlossary(const QString &path, QString &error)
{
    QList<Term> terms;
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly | QIODevice::Text)) {
        error = path + QStringLiteral(": ") + file.errorString();
        return terms;
    }
    int lineNumber = 0;
    while (!file.atEnd()) {
        ++lineNumber;
        const QString line = QString::fromUtf8(file.readLine()).chopped(1);
        if (line.isEmpty() || line.startsWith(QLatin1Char('#')))
            continue;
        const QStringList columns = line.split(QLatin1Char('\t'));
        if (columns.size() < 5) {
            error = QStringLiteral("%1:%2: expected 5 or 6 tab-separated columns").arg(path).arg(lineNumber);
            return {};
        }
        Term term;
        term.pattern = QRegularExpression(columns[0], QRegularExpression::CaseInsensitiveOption |
                                                          QRegularExpression::UseUnicodePropertiesOption);
        if (!term.pattern.isValid()) {
            error = QStringLiteral("%1:%2: %3").arg(path).arg(lineNumber).arg(term.pattern.errorString());
            return {};
        }
        for (int l = 0; l < 4; ++l)
            term.stems[l] = columns[l + 1].toLower().split(QLatin1Char('|'), Qt::SkipEmptyParts);
        if (columns.size() > 5)
            term.skipContexts = columns[5].split(QLatin1Char(','), Qt::SkipEmptyParts);
        terms.append(term);
    }
    return terms;
}

QList<Message> readMessages(const QString &path, QString &error)
{
    QList<Message> messages;
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly)) {
        error = path + QStringLiteral(": ") + file.errorString();
        return messages;
    }
    QXmlStreamReader xml(&file);
    QString context;
    Message current;
    while (!xml.atEnd()) {
        xml.readNext();
        if (!xml.isStartElement())
            continue;
        const auto name = xml.name();
        if (name == QLatin1String("name")) {
            context = xml.readElementText();
        } else if (name == QLatin1String("message")) {
            current = Message{context, {}, {}};
        } else if (name == QLatin1String("source")) {
            current.source = xml.readElementText();
        } else if (name == QLatin1String("translation")) {
            // A plain translation is its text; a plural one holds <numerusform> elements.
            QString text;
            while (!xml.atEnd()) {
                xml.readNext();
                if (xml.isCharacters())
                    text += xml.text();
                else if (xml.isStartElement() && xml.name() == QLatin1String("numerusform"))
                    current.translations.append(xml.readElementText());
                else if (xml.isEndElement() && xml.name() == QLatin1String("translation"))
                    break;
            }
            if (current.translations.isEmpty())
                current.translations.append(text);
            messages.append(current);
        }
    }
    if (xml.hasError())
        error = QStringLiteral("%1:%2: %3").arg(path).arg(xml.lineNumber()).arg(xml.errorString());
    return messages;
}

// The English source without what is kept as is in every language: command-line options
// (--elevate), identifiers written with hyphens (least-squares, global-bspline, trace-fit) and the
// command line's lower-case kind and command names that English prose never uses in that form.
QString withoutLiterals(QString source)
{
    static const QRegularExpression literals(
        QStringLiteral(R"(--[A-Za-z][\w-]*|\b[a-z]+(?:-[a-z]+)+\b|\b(?:interpolate|hermite|elevate|bezier)\b)"));
    return source.replace(literals, QStringLiteral(" "));
}

} // namespace

class TestGlossary final : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void everyTermIsTranslatedByTheGlossary()
    {
        QString error;
        const QList<Term> terms = readGlossary(QStringLiteral(KONTUR_I18N_DIR "/glossary.tsv"), error);
        QVERIFY2(error.isEmpty(), qPrintable(error));
        QVERIFY(terms.size() >= 30);
        QStringList misses;
        int checked = 0;
        for (int l = 0; l < 4; ++l) {
            const QString path = QStringLiteral(KONTUR_I18N_DIR "/kontur_%1.ts").arg(kLanguages[l]);
            const QList<Message> messages = readMessages(path, error);
            QVERIFY2(error.isEmpty(), qPrintable(error));
            QVERIFY(messages.size() > 400);
            for (const Message &m : messages) {
                const QString source = withoutLiterals(m.source);
                for (const Term &term : terms) {
                    if (term.skipContexts.contains(m.context) || !term.pattern.match(source).hasMatch())
                        continue;
                    for (const QString &translation : m.translations) {
                        ++checked;
                        const QString lower = translation.toLower();
                        const bool found = std::any_of(term.stems[l].begin(), term.stems[l].end(),
                                                       [&](const QString &stem) { return lower.contains(stem); });
                        if (!found)
                            misses.append(QStringLiteral("%1 [%2] /%3/ wants %4:\n    %5\n    %6")
                                              .arg(kLanguages[l], m.context, term.pattern.pattern(),
                                                   term.stems[l].join(QLatin1Char('|')), m.source.left(160),
                                                   translation.left(160)));
                    }
                }
            }
        }
        QVERIFY(checked > 500);            // the glossary's terms are the app's own words
        for (const QString &miss : misses) // each on its own: a test message is cut after 1,000 characters
            qWarning().noquote() << miss;
        QVERIFY2(misses.isEmpty(), qPrintable(QStringLiteral("%1 messages miss a glossary term").arg(misses.size())));
    }

    // The check itself: a message that drops the term is caught, an inflected form is not.
    void aMissIsFound()
    {
        QString error;
        const QList<Term> terms = readGlossary(QStringLiteral(KONTUR_I18N_DIR "/glossary.tsv"), error);
        QVERIFY(error.isEmpty());
        const auto curve = std::find_if(terms.begin(), terms.end(), [](const Term &t) {
            return t.pattern.match(QStringLiteral("Bézier curve")).hasMatch() &&
                   t.stems[3].contains(QStringLiteral("крив"));
        });
        QVERIFY(curve != terms.end());
        QVERIFY(QStringLiteral("кривую безье").contains(curve->stems[3].front())); // an inflected form
        QVERIFY(!QStringLiteral("линия безье").contains(curve->stems[3].front()));
        // Literal option values are no terms: "least-squares" and --elevate, but not "least squares".
        QCOMPARE(withoutLiterals(QStringLiteral("--elevate or least-squares")).trimmed(), QStringLiteral("or"));
        QCOMPARE(withoutLiterals(QStringLiteral("Least squares")), QStringLiteral("Least squares"));
    }
};

QTEST_GUILESS_MAIN(TestGlossary)
#include "tst_glossary.moc"
