package glint.render;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTimeoutPreemptively;
import static org.junit.jupiter.api.Assertions.assertTrue;

import glint.image.FrameBuffer;
import glint.scenefile.SceneLoader;
import java.nio.file.Path;
import java.time.Duration;
import java.util.concurrent.CancellationException;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.ExecutionException;
import org.junit.jupiter.api.Test;

/** The tracer's hook for long renders: tiles counted as they finish, and a frame cancelled from another thread. */
class TracerCancelTest {

    private static RenderScene scene() throws Exception {
        return RenderScene.compile(SceneLoader.load(Path.of("scenes/bench/spec-example.yaml")),
                new RenderSettings(Shading.COOK_TORRANCE, 5, 1e-3, 1e-9));
    }

    @Test
    void aFinishedFrameHasCountedEveryTile() throws Exception {
        try (Tracer tracer = new Tracer(2)) {
            tracer.render(scene(), new FrameBuffer(64, 48), 1, 0, 8);
            assertEquals(64, tracer.frameTiles());
            assertEquals(64, tracer.tilesDone());
        }
    }

    @Test
    void aCancelledFrameStopsAndEveryLaterRenderIsRefusedAtOnce() throws Exception {
        RenderScene scene = scene();
        FrameBuffer frame = new FrameBuffer(256, 256);
        try (Tracer tracer = new Tracer(1)) {
            // 4,096 tiles of 64 samples a pixel: cancelled after its first tile, the frame is far from done
            CompletableFuture<Void> render = CompletableFuture.runAsync(() -> tracer.render(scene, frame, 64, 0, 64));
            assertTimeoutPreemptively(Duration.ofSeconds(60), () -> {
                while (tracer.tilesDone() == 0) {
                    Thread.onSpinWait();
                }
                tracer.cancel();
                ExecutionException e = assertThrows(ExecutionException.class, render::get);
                assertTrue(e.getCause() instanceof CancellationException, e.toString());
            });
            assertTrue(tracer.tilesDone() < tracer.frameTiles(), tracer.tilesDone() + " tiles of " + tracer.frameTiles());
            assertThrows(CancellationException.class, () -> tracer.render(scene, frame, 1, 0, 8));
            assertEquals(0, tracer.tilesDone(), "a render after cancel() does no work");
        }
    }
}
