/** Command-line plumbing shared by the commands: converters and error handling. */
package io.rtaware.app.cli;
