package glint.ui.input;

import glint.math.Quaternion;
import glint.math.Vector3d;
import glint.scene.Camera;

/**
 * Flies the camera: a position and a unit quaternion, moved by how long each key was held. Flying is
 * in the camera's own frame (right +x, up +y, forward +z): W flies where the camera looks, Q and E
 * roll about its forward axis.
 *
 * <p>Turning keeps the horizon level: yaw turns about the world's up axis (+y) and pitch about the
 * camera's right axis, and pitch stops {@link #PITCH_LIMIT_DEGREES} short of straight up and down.
 * Neither changes the height of the camera's right axis above the horizon, so the horizon tilts only
 * when the user rolls; {@link #level} takes the roll out. In free flight (config key
 * {@code free_flight}) both turns are about the camera's own axes and pitch has no bound, as in a
 * plane. Turns compose as quaternions, re-normalised on every update so that the quaternion stays unit
 * however long one flies.
 */
public final class CameraController {

    /** Shift multiplies the flying speed by this. */
    public static final double FAST_FACTOR = 4;
    /** One wheel notch multiplies (towards the screen) or divides the flying speed by this. */
    public static final double WHEEL_FACTOR = 1.25;
    /** Degrees the camera turns per pixel of mouse drag. */
    public static final double DRAG_DEGREES_PER_PIXEL = 0.2;
    /** The wheel changes the speed by at most this factor either way. */
    static final double SPEED_FACTOR_LIMIT = 1024;
    /** A level camera's view stays this many degrees below straight up and above straight down. */
    public static final double PITCH_LIMIT_DEGREES = 1;

    /**
     * The field of view the zoom keys keep to, in degrees. A scene's view outside them (0.5, 170) is kept;
     * the keys move it toward them.
     */
    public static final double MIN_FOV = 1, MAX_FOV = 150;
    /** Holding a zoom key halves or doubles the field of view each second. */
    public static final double ZOOM_FACTOR_PER_SECOND = 2;
    /**
     * The lens keys: the first step up from a pinhole opens the aperture to this fraction of the focus
     * distance, and each step multiplies or divides it by {@link #APERTURE_STEP}; a step down from the
     * first one closes it (0, a pinhole). Chosen, not measured: at a 60 degree field of view a 1/64 lens
     * blurs a point at twice the focus by about 1% of the image's width, a visible first step.
     */
    public static final double FIRST_APERTURE = 1.0 / 64, APERTURE_STEP = Math.sqrt(2);
    /** The widest aperture the keys open, as a multiple of the focus distance. */
    public static final double WIDEST_APERTURE = 1;
    /** Where the orbit's point is when the ray under the mouse meets nothing: this far ahead, in scene units. */
    public static final double ORBIT_MISS_DISTANCE = 5;

    private static final double MAX_ELEVATION_SIN = Math.cos(Math.toRadians(PITCH_LIMIT_DEGREES));
    /**
     * The camera flies no farther from the origin than this in any coordinate (unless a scene put it
     * farther, and then no farther out): the longest length a scene has, so key C's block of it reads back.
     */
    static final double FARTHEST = 1e150;

    private Vector3d position;
    private Quaternion orientation;
    private double fovDegrees;
    /** The lens: its radius and the distance of the plane in focus, scene units (Camera's). */
    private double aperture, focus;
    private double moveSpeed;
    private double turnSpeedDegrees;
    private double speedFactor = 1;
    private boolean freeFlight;
    private Vector3d pivot; // what an orbit drag turns around, or null before the first

    /**
     * @param start            the initial pose and field of view
     * @param moveSpeed        scene units per second
     * @param turnSpeedDegrees degrees per second
     */
    public CameraController(Camera start, double moveSpeed, double turnSpeedDegrees) {
        reset(start);
        setSpeeds(moveSpeed, turnSpeedDegrees);
    }

    /** Puts the camera at a pose (for example the one of a reloaded scene). */
    public void reset(Camera camera) {
        this.position = camera.position();
        this.orientation = camera.orientation().normalize();
        this.fovDegrees = camera.fovDegrees();
        this.aperture = camera.aperture();
        this.focus = camera.focus();
    }

    public void setSpeeds(double newMoveSpeed, double newTurnSpeedDegrees) {
        this.moveSpeed = newMoveSpeed;
        this.turnSpeedDegrees = newTurnSpeedDegrees;
    }

    /** Turns about the camera's own axes without a pitch bound (true), or keeps the horizon level. */
    public void setFreeFlight(boolean free) {
        this.freeFlight = free;
    }

    public boolean freeFlight() {
        return freeFlight;
    }

    /**
     * The camera's roll in radians: how far it is turned about its forward axis from level (right axis
     * horizontal, top up), positive when the right side is up (rolling left). 0 for a level camera.
     */
    public double roll() {
        return roll(orientation);
    }

    public static double roll(Quaternion q) {
        return Math.atan2(q.right().y(), q.up().y());
    }

    /**
     * Takes the roll out at once: the camera keeps its position and the direction it looks in (as
     * far as the pitch bound allows), with its right axis horizontal. Returns whether it changed.
     */
    public boolean level() {
        Vector3d f = orientation.forward();
        if (Math.abs(roll()) < 1e-12 && Math.abs(f.y()) <= MAX_ELEVATION_SIN) {
            return false;
        }
        if (f.y() > MAX_ELEVATION_SIN || f.y() < -MAX_ELEVATION_SIN) {
            // straight up or down: the heading is where the camera's top (looking down) or bottom points
            Vector3d heading = orientation.up().scale(f.y() > 0 ? -1 : 1);
            Vector3d flat = new Vector3d(heading.x(), 0, heading.z());
            if (flat.length() < 1e-9) {
                flat = Vector3d.UNIT_Z;
            }
            double elevation = Math.copySign(Math.toRadians(90 - PITCH_LIMIT_DEGREES), f.y());
            f = flat.normalize().scale(Math.cos(elevation)).add(new Vector3d(0, Math.sin(elevation), 0));
        }
        Quaternion levelled = Quaternion.lookRotation(f, Vector3d.UNIT_Y);
        if (levelled.equals(orientation)) {
            return false;
        }
        orientation = levelled;
        return true;
    }

    /** The camera now. */
    public Camera camera() {
        return new Camera(position, orientation, fovDegrees, aperture, focus);
    }

    /** The flying speed now (config move_speed times the wheel's factor), without Shift. */
    public double speed() {
        return moveSpeed * speedFactor;
    }

    /** Applies one interval of input; returns whether the camera's pose changed. */
    public boolean apply(InputFrame in) {
        if (in.wheelNotches() != 0) {
            speedFactor *= Math.pow(WHEEL_FACTOR, -in.wheelNotches());
            speedFactor = Math.max(1 / SPEED_FACTOR_LIMIT, Math.min(SPEED_FACTOR_LIMIT, speedFactor));
        }
        boolean turned = turn(in);
        boolean moved = move(in);
        boolean zoomed = zoom(in);
        boolean orbited = orbit(in);
        return turned || moved || zoomed || orbited;
    }

    /** An orbit drag turns around {@code point} from now on (picked where the drag began). */
    public void orbitAround(Vector3d point) {
        this.pivot = point;
    }

    /**
     * ] (+1) or [ (-1): the aperture a step wider or narrower ({@link #FIRST_APERTURE}); returns whether it
     * changed.
     */
    public boolean stepAperture(int step) {
        double first = FIRST_APERTURE * focus, widest = WIDEST_APERTURE * focus;
        double next;
        if (step > 0) {
            // never narrower: an aperture a scene opened past the widest step stays as it is
            next = aperture == 0 ? first : Math.max(aperture, Math.min(widest, aperture * APERTURE_STEP));
        } else {
            next = aperture <= first * (1 + 1e-9) ? 0 : aperture / APERTURE_STEP;
        }
        next = Math.max(0, Math.min(FARTHEST, next));
        boolean changed = next != aperture;
        aperture = next;
        return changed;
    }

    /**
     * A click: the plane in focus through {@code point}, its distance along the view direction; returns
     * whether the focus changed (a point on or behind the camera's plane leaves it).
     */
    public boolean focusOn(Vector3d point) {
        double distance = point.sub(position).dot(orientation.forward());
        if (!(distance >= 1e-150 && distance <= FARTHEST) || distance == focus) {
            return false;
        }
        focus = distance;
        return true;
    }

    /** The lens for the overlay: {@code aperture 0.083  focus 5.3}, or that it is a pinhole. */
    public String lensNote() {
        return aperture == 0 ? "aperture 0: a pinhole, all in focus"
                : "aperture " + significant(aperture) + "  focus " + significant(focus);
    }

    /** Three significant digits, no exponent for numbers a scene is usually made of. */
    static String significant(double x) {
        java.math.BigDecimal d = new java.math.BigDecimal(x).round(new java.math.MathContext(3)).stripTrailingZeros();
        return x >= 1e-4 && x < 1e7 ? d.toPlainString() : d.toString();
    }

    /** The field of view for the overlay while Z or X is held: {@code fov 42.4 degrees}, and at a bound which one. */
    public String fovNote() {
        String note = String.format(java.util.Locale.ROOT, "fov %.1f degrees", fovDegrees);
        return fovDegrees <= MIN_FOV ? note + " (the narrowest)" : fovDegrees >= MAX_FOV ? note + " (the widest)" : note;
    }

    private boolean zoom(InputFrame in) {
        double seconds = in.seconds(Action.ZOOM_IN) - in.seconds(Action.ZOOM_OUT);
        if (seconds == 0) {
            return false;
        }
        double fov = fovDegrees * Math.pow(ZOOM_FACTOR_PER_SECOND, -seconds);
        // toward the bound, never past it; a scene's fov beyond it (170, 0.5) zooms back from where it is
        fov = seconds > 0 ? Math.max(Math.min(MIN_FOV, fovDegrees), fov) : Math.min(Math.max(MAX_FOV, fovDegrees), fov);
        boolean changed = fov != fovDegrees;
        fovDegrees = fov;
        return changed;
    }

    /**
     * Orbits the camera around the pivot: a drag right circles it to the left about the world's up axis (the
     * scene turns with the mouse, as on a turntable), a drag up lowers it about its own right axis, pitch
     * bounded as when turning; camera and view turn together, so the pivot stays where it is on the screen
     * and the horizon stays level.
     */
    private boolean orbit(InputFrame in) {
        if (pivot == null || in.orbitX() == 0 && in.orbitY() == 0) {
            return false;
        }
        double perPixel = Math.toRadians(DRAG_DEGREES_PER_PIXEL);
        double yaw = perPixel * in.orbitX();
        double pitch = boundedPitch(orientation, -perPixel * in.orbitY());
        Quaternion turn = Quaternion.fromAxisAngle(Vector3d.UNIT_Y, yaw);
        if (pitch != 0) {
            turn = turn.multiply(Quaternion.fromAxisAngle(orientation.right(), -pitch));
        }
        if (yaw == 0 && pitch == 0) {
            return false;
        }
        position = pivot.add(turn.rotate(position.sub(pivot)));
        orientation = turn.multiply(orientation).normalize();
        return true;
    }

    private boolean turn(InputFrame in) {
        double rate = Math.toRadians(turnSpeedDegrees);
        double drag = Math.toRadians(DRAG_DEGREES_PER_PIXEL);
        double yaw = rate * (in.seconds(Action.YAW_RIGHT) - in.seconds(Action.YAW_LEFT)) + drag * in.dragX();
        double pitchUp = rate * (in.seconds(Action.PITCH_UP) - in.seconds(Action.PITCH_DOWN)) - drag * in.dragY();
        double rollLeft = rate * (in.seconds(Action.ROLL_LEFT) - in.seconds(Action.ROLL_RIGHT));
        if (yaw == 0 && pitchUp == 0 && rollLeft == 0) {
            return false;
        }
        if (freeFlight) {
            // In the camera frame: +yaw about +y turns forward towards right; looking up is a negative
            // turn about +x; rolling left (right side up) is a positive turn about +z.
            Vector3d rotation = new Vector3d(finite(-pitchUp), finite(yaw), finite(rollLeft));
            orientation = orientation.multiply(Quaternion.fromRotationVector(rotation)).normalize();
            return true;
        }
        Quaternion q = orientation;
        yaw = finite(yaw);
        rollLeft = finite(rollLeft);
        double pitch = boundedPitch(q, finite(pitchUp)); // yaw about the world's up does not change the height
        if (rollLeft == 0 && yaw == 0 && pitch == 0) {
            return false; // at the bound
        }
        if (pitch != 0) { // about the camera's right axis, which stays where it is
            q = q.multiply(Quaternion.fromAxisAngle(Vector3d.UNIT_X, -pitch));
        }
        if (rollLeft != 0) { // about the forward axis: the view's height stays
            q = q.multiply(Quaternion.fromAxisAngle(Vector3d.UNIT_Z, rollLeft));
        }
        if (yaw != 0) { // about the world's up: a turn on the spot, whatever the pitch
            q = Quaternion.fromAxisAngle(Vector3d.UNIT_Y, yaw).multiply(q);
        }
        orientation = q.normalize();
        return true;
    }

    /**
     * The part of a pitch of {@code pitchUp} radians that keeps the view within the bound. Pitching by t
     * turns forward to f cos t + u sin t, whose height is A cos(t - phase): highest at t = phase, lowest
     * half a turn on. Measured from the top (s = t - phase), an upright camera is allowed on the arc
     * between the bottom bound and the top bound, and the pitch is clamped to its ends. (A camera rolled
     * so far that its view cannot reach the bound stops at the top or the bottom itself.) A camera off
     * the arc (a scene's camera looking straight down) may turn only as far as the arc's far end.
     */
    private static double boundedPitch(Quaternion q, double pitchUp) {
        if (pitchUp == 0) {
            return 0;
        }
        double fy = q.forward().y();
        double uy = q.up().y();
        double amplitude = Math.hypot(fy, uy);
        // the top's forbidden half-width; a rolled camera that cannot reach the bound stops where it
        // looks highest (or lowest) rather than turning over
        double reach = amplitude > MAX_ELEVATION_SIN ? Math.acos(MAX_ELEVATION_SIN / amplitude) : 0;
        double s = -Math.atan2(uy, fy); // where the camera is, measured from the top
        // an upright camera (its top above the horizon) is on the arc from the bottom bound to the top one
        double low = -Math.PI + reach;
        double high = -reach;
        if (s >= low - 1e-9 && s <= high + 1e-9) { // on it, or a rounding error past a bound: no further
            low = Math.min(low, s);
            high = Math.max(high, s);
        } else if (s > high) { // beyond the top or upside down: either way round, to the arc's far end
            high += 2 * Math.PI;
        } else { // beyond the bottom
            low -= 2 * Math.PI;
        }
        double pitch = Math.max(low, Math.min(high, s + pitchUp)) - s;
        return Math.abs(pitch) < 1e-12 ? 0 : pitch; // at the bound: no turn, not a rounding error's worth
    }

    /**
     * A turn in radians as a finite number: a turn_speed near the largest double held for long is more
     * than a double, and a turn of any size is a finite number of whole turns and a remainder anyway.
     */
    private static double finite(double radians) {
        return Math.max(-Double.MAX_VALUE, Math.min(Double.MAX_VALUE, radians));
    }

    /** The largest coordinate's size, NaN or infinity when there is one. */
    private static double farthest(Vector3d p) {
        return Math.max(Math.abs(p.x()), Math.max(Math.abs(p.y()), Math.abs(p.z())));
    }

    private boolean move(InputFrame in) {
        double speed = speed() * (in.fast() ? FAST_FACTOR : 1);
        Vector3d local = new Vector3d(
                in.seconds(Action.RIGHT) - in.seconds(Action.LEFT),
                in.seconds(Action.UP) - in.seconds(Action.DOWN),
                in.seconds(Action.FORWARD) - in.seconds(Action.BACK)).scale(speed);
        if (local.x() == 0 && local.y() == 0 && local.z() == 0) {
            return false;
        }
        Vector3d moved = freeFlight ? position.add(orientation.rotate(local))
                // R and F along the world's up: a pitched camera does not drift forwards or back
                : position.add(orientation.rotate(new Vector3d(local.x(), 0, local.z()))).add(new Vector3d(0, local.y(), 0));
        if (!(farthest(moved) <= Math.max(FARTHEST, farthest(position)))) { // a move_speed of 1e308: it stays
            return false;
        }
        position = moved;
        return true;
    }
}
