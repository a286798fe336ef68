/**
 * Studies of Glint's numerics: how much accuracy each millisecond buys ({@link glint.study.SpeedAccuracy})
 * and where textbook methods fail beside Glint's ({@link glint.study.Stability}). Nothing here is on
 * the render path; the renderer is used only through its public API.
 */
package glint.study;
