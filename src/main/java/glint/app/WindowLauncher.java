package glint.app;

import glint.config.Config;
import java.awt.GraphicsEnvironment;
import java.io.PrintWriter;
import java.nio.file.Path;

/** Opens the interactive window, or explains why it cannot. */
final class WindowLauncher {

    private WindowLauncher() {
    }

    static int open(Path scenePath, Config config, PrintWriter err) {
        if (GraphicsEnvironment.isHeadless()) {
            err.println("glint: no display available for the window; render a still with "
                    + "--output FILE.png (for example: java -jar target/glint.jar --output out.png)");
            return Main.FAILURE;
        }
        err.println("glint: the window is not yet available; render a still with --output FILE.png");
        return Main.FAILURE;
    }
}
