package glint.render;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTimeoutPreemptively;

import glint.image.FrameBuffer;
import glint.scenefile.SceneLoader;
import java.nio.file.Path;
import java.time.Duration;
import org.junit.jupiter.api.Test;

/**
 * A render thread that ends on an error outside a frame's work (memory running out while it waits for the
 * next frame) fails a frame with that error, never leaves it waiting, and the frames after it render as a
 * new tracer's would.
 */
class TracerThreadEndTest {

    private static RenderScene scene(LightTransport transport) throws Exception {
        return RenderScene.compile(SceneLoader.load(Path.of("scenes/caustics.yaml")),
                new RenderSettings(Shading.COOK_TORRANCE, 5, 0, 1e-9).withTransport(transport));
    }

    private static float[] fresh(RenderScene scene) {
        FrameBuffer frame = new FrameBuffer(40, 30);
        try (Tracer tracer = new Tracer(2)) {
            tracer.render(scene, frame, 1, 3, 4);
        }
        return frame.rgb();
    }

    @Test
    void aThreadThatEndsBetweenFramesFailsAFrameAndTheNextRendersAsBefore() throws Exception {
        for (LightTransport transport : new LightTransport[] {LightTransport.WHITTED, LightTransport.BDPT}) {
            RenderScene scene = scene(transport);
            float[] expected = fresh(scene);
            OutOfMemoryError error = new OutOfMemoryError("Java heap space");
            FrameBuffer frame = new FrameBuffer(40, 30);
            try (Tracer tracer = new Tracer(2)) {
                tracer.render(scene, frame, 1, 3, 4);
                tracer.failBetweenFrames(error);
                assertTimeoutPreemptively(Duration.ofSeconds(60), () -> {
                    // the thread ends after its share of the next frame: that frame or the one after fails
                    RenderException failed = null;
                    for (int frameCount = 0; frameCount < 2 && failed == null; frameCount++) {
                        try {
                            tracer.render(scene, frame, 1, 3, 4);
                        } catch (RenderException e) {
                            failed = e;
                        }
                    }
                    assertSame(error, failed == null ? null : failed.getCause(), transport.toString());
                    assertEquals("a render thread ended: java.lang.OutOfMemoryError: Java heap space",
                            failed.getMessage());
                    tracer.render(scene, frame, 1, 3, 4);
                });
                assertArrayEquals(expected, frame.rgb(), transport + ": the frame after, by a new crew");
            }
        }
    }

    @Test
    void aFrameAfterCloseIsRefused() throws Exception {
        RenderScene scene = scene(LightTransport.WHITTED);
        Tracer tracer = new Tracer(2);
        tracer.close();
        assertThrows(IllegalStateException.class, () -> tracer.render(scene, new FrameBuffer(8, 8), 1, 0, 2));
    }
}
