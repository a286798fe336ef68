package glint.ui.capture;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.io.IOException;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;

/** What the window's still says when its image cannot be written. */
class StillRenderTest {

    @Test
    void whyAStillFailedNamesTheImageNotTheFileTheSystemNamed() {
        Path png = Path.of("/photos/ball.png");
        assertEquals("/photos/ball.png: permission denied",
                StillRender.why(new java.nio.file.AccessDeniedException("/photos/.ball.png.3a8.part"), png));
        assertEquals("/photos/ball.png: No space left on device", StillRender.why(
                new java.nio.file.FileSystemException("/photos/.ball.png.3a8.part", null, "No space left on device"), png));
        assertEquals("/photos/ball.png: File too large", StillRender.why(new IOException("File too large"), png));
    }
}
