package glint.ui.scenes;

import glint.input.InputException;
import glint.input.TextFiles;
import glint.scene.Scene;
import java.io.IOException;
import java.io.InputStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.NoSuchFileException;
import java.nio.file.Path;
import java.nio.file.attribute.BasicFileAttributes;
import java.util.Arrays;
import java.util.List;
import java.util.Objects;
import java.util.concurrent.Executors;
import java.util.concurrent.ScheduledExecutorService;
import java.util.concurrent.TimeUnit;

/**
 * Watches the scene file by reading it a few times a second (robust where file-system events are
 * not: editors that save by renaming, network folders, coarse timestamps) and hands every changed
 * version, loaded or failed, to a listener. Reading a small YAML file four times a second costs
 * nothing noticeable.
 *
 * <p>A file being saved is never loaded half written: a changed content is loaded only when the next
 * read, one period later, finds the same bytes with the same modification time (saves that follow each
 * other can have the same first half: equal bytes alone would take a file still being written for one
 * that stayed the same), and the result is dropped if the file changed while it was loading. A save that
 * stops half way for less than a period therefore never shows; this matters most where the first half of
 * a scene is itself a valid, smaller scene (the objects cut off after the first few).
 */
public final class SceneWatcher implements AutoCloseable {

    /** How often the file is read; a change must stay the same for one period to be loaded. */
    public static final long PERIOD_MILLIS = 250;

    /** What the watcher reports. */
    public interface Listener {

        void loaded(Scene scene);

        void failed(InputException error);

        /** A version of {@code file} loaded; a listener that shows another file by now drops it. */
        default void loaded(Path file, Scene scene) {
            loaded(scene);
        }

        /** A version of {@code file} does not load; a listener that shows another file by now drops it. */
        default void failed(Path file, InputException error) {
            failed(error);
        }
    }

    /** What runs the watcher's reads: a thread of its own, or a test that says when a period has passed. */
    interface Timer extends AutoCloseable {

        /** Runs {@code read} every {@code periodMillis} ms, the first time one period from now. */
        void every(long periodMillis, Runnable read);

        /** No more reads. */
        @Override
        void close();
    }

    /** The reads on a daemon thread, {@code glint-scene-watcher}. */
    private static final class ThreadTimer implements Timer {

        private final ScheduledExecutorService executor = Executors.newSingleThreadScheduledExecutor(r -> {
            Thread t = new Thread(r, "glint-scene-watcher");
            t.setDaemon(true);
            return t;
        });

        @Override
        public void every(long periodMillis, Runnable read) {
            executor.scheduleWithFixedDelay(read, periodMillis, periodMillis, TimeUnit.MILLISECONDS);
        }

        @Override
        public void close() {
            executor.shutdownNow();
        }
    }

    private final SceneSource source;
    private Path file; // the source's scene when last read
    private final Timer timer;
    private volatile Listener listener;
    private byte[] last;     // the content last reported (at start: the content loaded before watching)
    private byte[] pending;  // a new content read once, loaded if the next read finds it again
    private Object pendingStamp; // and the file's modification time, size and identity when it was read
    private boolean hasPending;

    /**
     * Takes the file's current content as known (call it before loading the scene, so that no change
     * in between is missed); only later changes are reported. The scene is loaded with
     * {@link SceneSource#loadScene}, within the source's limits.
     */
    public SceneWatcher(SceneSource source) {
        this(source, new ThreadTimer());
    }

    /** A watcher whose reads {@code timer} runs (tests: when they say a period has passed). */
    SceneWatcher(SceneSource source, Timer timer) {
        this.source = source;
        this.file = source.scenePath();
        this.last = read();
        this.timer = timer;
    }

    /** Starts reading the file every {@link #PERIOD_MILLIS} ms, reporting changes to {@code to}. */
    public void start(Listener to) {
        this.listener = to;
        timer.every(PERIOD_MILLIS, this::pollSafely);
    }

    /**
     * Reads the file once. A content that differs from the one last reported is remembered; if the next
     * read, a period later, finds it again (it stayed the same for a period), it is loaded and reported. A
     * file that is gone is reported the same way (gone for two reads: an editor saving by rename is not).
     */
    private void poll() {
        if (!file.equals(source.scenePath())) { // the window opened another scene: watch that one from now
            file = source.scenePath();
            last = read();
            hasPending = false;
            return;
        }
        Object stamp = stamp();
        byte[] now = read();
        if (Arrays.equals(now, last)) {
            hasPending = false; // unchanged, or back to what is on screen
            return;
        }
        if (!hasPending || !Arrays.equals(now, pending) || !Objects.equals(stamp, pendingStamp)) {
            pending = now; // changed since the last read: maybe still being written
            pendingStamp = stamp;
            hasPending = true;
            return;
        }
        hasPending = false;
        Scene scene = null;
        InputException problem = null;
        try {
            scene = source.loadScene(file); // the file read, even if the window has opened another since
        } catch (InputException e) {
            problem = e;
        } catch (OutOfMemoryError e) { // reported like any problem of this version, once; the last good scene stays
            problem = new InputException(file.toString(), 0, 0, "not loaded: out of memory ("
                    + e.getMessage() + "); start Java with a larger -Xmx");
        }
        Object stampAfter = stamp();
        byte[] after = read();
        if (!Arrays.equals(after, now) || !Objects.equals(stampAfter, stamp)) {
            pending = after; // written again while it loaded: what loaded may be half of it
            pendingStamp = stampAfter;
            hasPending = true;
            return;
        }
        last = now;
        if (problem == null) {
            listener.loaded(file, scene);
        } else {
            listener.failed(file, problem);
        }
    }

    /** One read on the timer's thread: whatever goes wrong is reported, and the reads go on (a timer's task that throws is never run again). */
    private void pollSafely() {
        try {
            poll();
        } catch (RuntimeException | Error e) {
            try {
                listener.failed(new InputException(source.scenePath().toString(), 0, 0, "cannot watch: " + e));
            } catch (RuntimeException | Error again) {
                // the listener cannot take it either: the next read tries again
            }
        }
    }

    /**
     * The file's bytes; null when it does not exist. A file larger than the scene limit is not read (the
     * loader refuses it): its size and time stand for its content. So does an unreadable one's error,
     * and a special file's type (a FIFO, a device): it is never opened, so the watcher never blocks.
     */
    private byte[] read() {
        try {
            String special = TextFiles.notARegularFile(file); // a FIFO is never opened: its read would block
            if (special != null) {
                return marker(special);
            }
            long size = Files.size(file);
            long max = source.limits().maxFileBytes();
            if (size > max) {
                return marker("too large: " + size + " bytes, modified " + Files.getLastModifiedTime(file));
            }
            try (InputStream in = Files.newInputStream(file)) {
                return in.readNBytes((int) Math.min(Integer.MAX_VALUE - 16, max + 1)); // bounded if it grows
            }
        } catch (NoSuchFileException e) {
            return null;
        } catch (IOException e) {
            return marker("unreadable: " + e); // the loader says why
        }
    }

    /** The file's modification time, size and identity (its inode), or null when it has none to tell. */
    private Object stamp() {
        try {
            BasicFileAttributes a = Files.readAttributes(file, BasicFileAttributes.class);
            return List.of(a.lastModifiedTime(), a.size(), String.valueOf(a.fileKey()));
        } catch (IOException | RuntimeException e) {
            return null; // gone, or unreadable: the bytes (a marker) say so
        }
    }

    private static byte[] marker(String text) {
        return ("\0glint-watcher\0" + text).getBytes(StandardCharsets.UTF_8);
    }

    @Override
    public void close() {
        timer.close();
    }
}
