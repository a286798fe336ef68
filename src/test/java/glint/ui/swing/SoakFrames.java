package glint.ui.swing;

import glint.image.FrameBuffer;
import glint.image.Srgb;
import glint.math.Vector3d;
import glint.render.RenderScene;
import glint.render.Tracer;
import glint.scene.Scene;
import glint.ui.engine.Engine;
import glint.ui.frames.FrameRenderer;
import glint.ui.screen.Presenter;
import glint.ui.screen.ShownFrame;
import java.awt.image.BufferedImage;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.concurrent.CountDownLatch;

/**
 * How {@link WindowSoakTest} tells a torn frame: every render stamps the sky with its own blue code, and a
 * checker in front of the display looks at each image handed over for a sky of any other code.
 */
final class SoakFrames {

    /** The first blue code of the sky stamp; codes run through {@link #STAMPS} values from it. */
    static final int STAMP_FIRST = 20;
    static final int STAMPS = 200;

    private SoakFrames() {
    }

    /** The linear value whose 8-bit sRGB code is {@code code}, at the middle of the code's interval. */
    static double linear(int code) {
        double v = code / 255.0;
        return v <= 0.04045 ? v / 12.92 : Math.pow((v + 0.055) / 1.055, 2.4);
    }

    /**
     * The tracer, on the engine's scene and camera, but with the sky stamped: render n has a sky of blue
     * code STAMP_FIRST + n mod STAMPS. Remembers the code the sky must have in the image made of it.
     */
    static final class StampingTrace implements FrameRenderer.TraceCall {

        private final CountDownLatch ready = new CountDownLatch(1);
        private volatile Engine engine;
        private long renders;
        private double passSum;
        private int passes;
        volatile int expectedSky = -1;
        volatile long movingFrames;
        volatile long stillPasses;

        void engine(Engine e) {
            engine = e;
            ready.countDown();
        }

        @Override
        public void trace(Tracer tracer, RenderScene scene, FrameBuffer target, int samples, int pass, int count, int divider) {
            try {
                ready.await();
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
                throw new IllegalStateException(e);
            }
            int code = STAMP_FIRST + (int) (renders++ % STAMPS);
            float sky = (float) linear(code);
            Scene s = engine.scene();
            RenderScene stamped = RenderScene.compile(new Scene(engine.camera(), new Vector3d(0, 0, sky), s.ambient(),
                    s.lights(), s.objects()), scene.settings());
            TRACER.trace(tracer, stamped, target, samples, pass, count, divider);
            if (pass == WHOLE_FRAME) {
                expectedSky = Srgb.to8Bit(sky);
                movingFrames++;
            } else { // the accumulator's average of the passes so far, in its arithmetic
                if (pass == 0) {
                    passSum = 0;
                    passes = 0;
                }
                passSum += sky;
                passes++;
                expectedSky = Srgb.to8Bit((float) (passSum * (1.0 / passes)));
                stillPasses++;
            }
        }
    }

    /** In front of the display: checks every new image handed over, then passes it on. */
    static final class CheckingPresenter implements Presenter {

        private final Presenter display;
        private final StampingTrace trace;
        private BufferedImage previous;
        private int previousHash;
        private int[] pixels = new int[0];
        volatile long images;
        volatile long presents;
        volatile long torn;
        volatile long changedAfterHandover;
        volatile long imagesWithSky;
        volatile long skyPixels;
        final List<String> problems = new ArrayList<>();

        CheckingPresenter(Presenter display, StampingTrace trace) {
            this.display = display;
            this.trace = trace;
        }

        @Override
        public void present(ShownFrame frame) {
            presents++;
            BufferedImage image = frame.image();
            if (image != null && image != previous) {
                if (previous != null && hash(previous) != previousHash) {
                    changedAfterHandover++;
                    problem("frame before " + frame.serial() + " changed after it was handed over");
                }
                check(image, frame);
                previous = image;
                previousHash = hash(image);
            }
            display.present(frame);
        }

        private void check(BufferedImage image, ShownFrame frame) {
            images++;
            int expected = trace.expectedSky;
            int n = read(image);
            long sky = 0;
            long wrong = 0;
            int firstWrong = -1;
            for (int i = 0; i < n; i++) {
                int p = pixels[i];
                if ((p & 0xffff00) == 0) { // no red, no green: nothing but sky
                    if ((p & 0xff) == expected) {
                        sky++;
                    } else {
                        wrong++;
                        firstWrong = firstWrong < 0 ? i : firstWrong;
                    }
                }
            }
            skyPixels += sky;
            if (sky + wrong > 0) {
                imagesWithSky++;
            }
            if (wrong > 0) {
                torn++;
                problem(String.format(Locale.ROOT, "frame %d (%dx%d, %s): %d sky pixels not of blue %d, the first at"
                        + " (%d, %d) blue %d", frame.serial(), image.getWidth(), image.getHeight(),
                        frame.stats().moving() ? "moving" : "pass " + frame.stats().samplesDone(), wrong, expected,
                        firstWrong % image.getWidth(), firstWrong / image.getWidth(), pixels[firstWrong] & 0xff));
            }
        }

        private int read(BufferedImage image) {
            int n = image.getWidth() * image.getHeight();
            if (pixels.length < n) {
                pixels = new int[n];
            }
            image.getRaster().getDataElements(0, 0, image.getWidth(), image.getHeight(), pixels); // a copy
            return n;
        }

        private int hash(BufferedImage image) {
            int n = read(image);
            int h = 1;
            for (int i = 0; i < n; i++) {
                h = 31 * h + pixels[i];
            }
            return h;
        }

        private void problem(String text) {
            synchronized (problems) {
                if (problems.size() < 20) {
                    problems.add(text);
                }
            }
        }

        @Override
        public void title(String title) {
            display.title(title);
        }
    }

}
