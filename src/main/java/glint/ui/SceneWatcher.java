package glint.ui;

import glint.input.InputException;
import glint.scene.Scene;
import glint.scene.SceneLoader;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.NoSuchFileException;
import java.nio.file.Path;
import java.util.Arrays;
import java.util.concurrent.Executors;
import java.util.concurrent.ScheduledExecutorService;
import java.util.concurrent.TimeUnit;

/**
 * Watches the scene file by reading it a few times a second (robust where file-system events are
 * not: editors that save by renaming, network folders, coarse timestamps) and hands every changed
 * version, loaded or failed, to a listener. Reading a small YAML file four times a second costs
 * nothing noticeable.
 */
public final class SceneWatcher implements AutoCloseable {

    /** How often the file is read. */
    public static final long PERIOD_MILLIS = 250;

    /** What the watcher reports. */
    public interface Listener {

        void loaded(Scene scene);

        void failed(InputException error);
    }

    private final Path file;
    private final ScheduledExecutorService timer;
    private volatile Listener listener;
    private byte[] last;
    private boolean missingOnce;

    /**
     * Takes the file's current content as known (call it before loading the scene, so that no change
     * in between is missed); only later changes are reported.
     */
    public SceneWatcher(Path file) {
        this.file = file;
        this.last = read();
        this.timer = Executors.newSingleThreadScheduledExecutor(r -> {
            Thread t = new Thread(r, "glint-scene-watcher");
            t.setDaemon(true);
            return t;
        });
    }

    /** Starts reading the file every {@link #PERIOD_MILLIS} ms, reporting changes to {@code to}. */
    public void start(Listener to) {
        this.listener = to;
        timer.scheduleWithFixedDelay(this::pollSafely, PERIOD_MILLIS, PERIOD_MILLIS, TimeUnit.MILLISECONDS);
    }

    /** Reports changes to {@code to} from the next {@link #poll} on, without a timer (tests). */
    void listen(Listener to) {
        this.listener = to;
    }

    /** Checks the file once; reports a change. */
    void poll() {
        byte[] now = read();
        if (now == null && !missingOnce && last != null) {
            missingOnce = true; // an editor saving by rename: look again before reporting it gone
            return;
        }
        missingOnce = false;
        if (Arrays.equals(now, last)) {
            return;
        }
        last = now;
        try {
            listener.loaded(SceneLoader.load(file));
        } catch (InputException e) {
            listener.failed(e);
        }
    }

    private void pollSafely() {
        try {
            poll();
        } catch (RuntimeException e) {
            listener.failed(new InputException(file.toString(), 0, 0, "cannot watch: " + e));
        }
    }

    private byte[] read() {
        try {
            return Files.readAllBytes(file);
        } catch (NoSuchFileException e) {
            return null;
        } catch (IOException e) {
            return new byte[0]; // unreadable: reported by the loader
        }
    }

    @Override
    public void close() {
        timer.shutdownNow();
    }
}
