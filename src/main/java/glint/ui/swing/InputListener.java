package glint.ui.swing;

import glint.ui.capture.StillRender;
import glint.ui.input.Action;
import glint.ui.input.InputState;
import glint.ui.input.KeyBindings;
import glint.ui.screen.ShownFrame;
import java.awt.event.ComponentAdapter;
import java.awt.event.ComponentEvent;
import java.awt.event.FocusAdapter;
import java.awt.event.FocusEvent;
import java.awt.event.KeyAdapter;
import java.awt.event.KeyEvent;
import java.awt.event.MouseAdapter;
import java.awt.event.MouseEvent;
import java.awt.event.MouseWheelEvent;
import java.util.HashSet;
import java.util.Set;
import javax.swing.SwingUtilities;

/**
 * Turns the display's AWT events (on the Swing event thread) into {@link InputState} changes through
 * the {@link KeyBindings} table. Overlay and help toggles stay on the event thread: they only repaint.
 */
final class InputListener {

    private final InputState input;
    private final Display display;
    private final Runnable quit;
    private final Set<Integer> commandKeysDown = new HashSet<>(); // event thread only
    private int lastX;
    private int lastY;
    private boolean orbiting; // a drag that began with Ctrl or the middle button

    private InputListener(InputState input, Display display, Runnable quit) {
        this.input = input;
        this.display = display;
        this.quit = quit;
    }

    /**
     * Listens to the display's keys, mouse, focus and size; {@code quit} is told of Esc besides the engine,
     * so that the window ends even while the engine is stuck in a frame.
     */
    static void attach(InputState input, Display display, Runnable quit) {
        InputListener l = new InputListener(input, display, quit);
        display.addKeyListener(l.keys());
        MouseAdapter mouse = l.mouse();
        display.addMouseListener(mouse);
        display.addMouseMotionListener(mouse);
        display.addMouseWheelListener(mouse);
        display.addFocusListener(new FocusAdapter() {
            @Override
            public void focusLost(FocusEvent e) {
                input.releaseAll(); // no key stays held while another window has the keyboard
                l.commandKeysDown.clear();
            }
        });
        display.addComponentListener(new ComponentAdapter() {
            @Override
            public void componentResized(ComponentEvent e) {
                input.resize(display.getWidth(), display.getHeight());
            }
        });
    }

    private KeyAdapter keys() {
        return new KeyAdapter() {
            @Override
            public void keyPressed(KeyEvent e) {
                Action action = KeyBindings.forKeyCode(e.getKeyCode());
                if (action == null) {
                    return;
                }
                e.consume();
                if (action.isHeld()) {
                    input.press(action);
                } else if (commandKeysDown.add(e.getKeyCode())) { // not again while auto-repeating
                    if (action == Action.VIEW) {
                        input.view(KeyBindings.viewOf(e.getKeyCode()));
                    } else if ((action == Action.RENDER_STILL || action == Action.QUIT) && stillShown()) {
                        command(Action.CANCEL_STILL); // what the overlay said when the key went down
                    } else if (action == Action.RENDER_STILL && e.isShiftDown()) {
                        command(Action.RENDER_STILL_PFM);
                    } else {
                        command(action);
                    }
                }
            }

            @Override
            public void keyReleased(KeyEvent e) {
                commandKeysDown.remove(e.getKeyCode());
                Action action = KeyBindings.forKeyCode(e.getKeyCode());
                if (action != null && action.isHeld()) {
                    input.release(action);
                }
            }

            @Override
            public void keyTyped(KeyEvent e) {
                Action action = KeyBindings.forChar(e.getKeyChar());
                if (action != null) {
                    e.consume();
                    command(action);
                }
            }
        };
    }

    private MouseAdapter mouse() {
        return new MouseAdapter() {
            @Override
            public void mousePressed(MouseEvent e) {
                display.requestFocusInWindow();
                lastX = e.getX();
                lastY = e.getY();
                orbiting = SwingUtilities.isMiddleMouseButton(e) || e.isControlDown();
                if (orbiting) {
                    input.orbitFrom(e.getX(), e.getY());
                }
            }

            @Override
            public void mouseReleased(MouseEvent e) {
                if ((e.getModifiersEx() & (MouseEvent.BUTTON1_DOWN_MASK | MouseEvent.BUTTON2_DOWN_MASK
                        | MouseEvent.BUTTON3_DOWN_MASK)) == 0) {
                    orbiting = false;
                }
            }

            /** A plain left click, without a drag between press and release: focus there (Ctrl + drag orbits). */
            @Override
            public void mouseClicked(MouseEvent e) {
                if (SwingUtilities.isLeftMouseButton(e) && !e.isControlDown()) {
                    input.focusAt(e.getX(), e.getY());
                }
            }

            @Override
            public void mouseDragged(MouseEvent e) {
                if (orbiting) {
                    input.orbit(e.getX() - lastX, e.getY() - lastY);
                } else if (SwingUtilities.isLeftMouseButton(e) || SwingUtilities.isRightMouseButton(e)) {
                    input.drag(e.getX() - lastX, e.getY() - lastY);
                }
                lastX = e.getX();
                lastY = e.getY();
            }

            @Override
            public void mouseWheelMoved(MouseWheelEvent e) {
                input.wheel(e.getWheelRotation());
            }
        };
    }

    /** Whether the overlay on screen says a still is under way (Enter and Esc then cancel it). */
    private boolean stillShown() {
        ShownFrame shown = display.shown();
        return shown != null && StillRender.underWay(shown.stats().message());
    }

    private void command(Action action) {
        switch (action) {
            case TOGGLE_OVERLAY -> display.toggleOverlay();
            case TOGGLE_HELP -> display.toggleHelp();
            case QUIT -> {
                input.command(action);
                quit.run();
            }
            default -> input.command(action);
        }
    }
}
