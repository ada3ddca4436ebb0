// The RigidLab editor: sets up the application and opens the scene named on the command line, if any.
#include "HugePages.h"
#include "MainWindow.h"
#include "settings/Translation.h"

#include <QApplication>
#include <QCommandLineParser>
#include <QLibraryInfo>
#include <QLocale>
#include <QSettings>
#include <QSurfaceFormat>
#include <QTranslator>

int main(int argc, char* argv[]) {
    rl::app::useHugePages(argv);
    // The viewport needs a 3.3 core context; the format must be set before the application exists.
    QSurfaceFormat format;
    format.setVersion(3, 3);
    format.setProfile(QSurfaceFormat::CoreProfile);
    format.setDepthBufferSize(24);
    format.setStencilBufferSize(8);
    // No multisampling: under Mesa llvmpipe 4x MSAA on the window surface costs 77 -> 129 ms CPU per 5,000-body
    // frame (measured); the viewport's outline keeps edges readable without it.
    QSurfaceFormat::setDefaultFormat(format);

    QApplication app(argc, argv);
    QApplication::setOrganizationName("RigidLab");
    QApplication::setApplicationName("RigidLab");
    QApplication::setApplicationVersion(RIGIDLAB_VERSION);

    // The language follows the "ui/language" setting, else the system locale.
    QSettings settings;
    const QString language = settings.value("ui/language").toString();
    const QLocale locale = language.isEmpty() ? QLocale::system() : QLocale(language);
    QTranslator translator;
    if (rl::loadEditorTranslation(translator, locale))
        QApplication::installTranslator(&translator);
    QTranslator qtTranslator;
    if (qtTranslator.load(locale, "qtbase", "_", QLibraryInfo::path(QLibraryInfo::TranslationsPath)))
        QApplication::installTranslator(&qtTranslator);

    QCommandLineParser parser;
    parser.setApplicationDescription(QApplication::translate("main", "RigidLab rigid-body scene editor"));
    parser.addHelpOption();
    parser.addVersionOption();
    parser.addPositionalArgument("scene", QApplication::translate("main", "Scene file to open."), "[scene]");
    parser.process(app);

    rl::MainWindow window;
    window.show();
    if (!parser.positionalArguments().isEmpty())
        window.openFile(parser.positionalArguments().constFirst());
    return app.exec();
}
