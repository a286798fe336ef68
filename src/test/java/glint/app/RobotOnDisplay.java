package glint.app;

import java.awt.Robot;
import java.awt.event.InputEvent;
import java.awt.event.KeyEvent;
import java.io.BufferedReader;
import java.io.InputStreamReader;
import java.nio.charset.StandardCharsets;

/**
 * A user's mouse, keyboard and eyes on the display in {@code DISPLAY}, for a test driving the real program
 * in another process: reads commands from standard input, one a line ({@code click X Y}, {@code key ENTER}
 * with a {@link KeyEvent} {@code VK_} name, {@code shown X Y}: waits, a bounded time, until the pixel there
 * is not black, a window showing a frame), and answers {@code ok} once the display has taken each, or
 * {@code not shown}.
 */
public final class RobotOnDisplay {

    private RobotOnDisplay() {
    }

    public static void main(String[] args) throws Exception {
        Robot robot = new Robot();
        BufferedReader in = new BufferedReader(new InputStreamReader(System.in, StandardCharsets.UTF_8));
        for (String line = in.readLine(); line != null; line = in.readLine()) {
            String[] words = line.trim().split(" ");
            if (words[0].equals("click")) {
                robot.mouseMove(Integer.parseInt(words[1]), Integer.parseInt(words[2]));
                robot.mousePress(InputEvent.BUTTON1_DOWN_MASK);
                robot.mouseRelease(InputEvent.BUTTON1_DOWN_MASK);
            } else if (words[0].equals("shown")) {
                if (!shown(robot, Integer.parseInt(words[1]), Integer.parseInt(words[2]))) {
                    System.out.println("not shown");
                    System.out.flush();
                    continue;
                }
            } else if (words[0].equals("key")) {
                int code = KeyEvent.class.getField("VK_" + words[1]).getInt(null);
                robot.keyPress(code);
                robot.keyRelease(code);
            }
            robot.waitForIdle();
            System.out.println("ok");
            System.out.flush();
        }
    }

    /** Polls the pixel until it is not black, for at most a minute. */
    private static boolean shown(Robot robot, int x, int y) throws InterruptedException {
        long deadline = System.nanoTime() + 60_000_000_000L;
        while (System.nanoTime() < deadline) {
            if ((robot.getPixelColor(x, y).getRGB() & 0xffffff) != 0) {
                return true;
            }
            Thread.sleep(10); // a bounded poll of the screen
        }
        return false;
    }
}
