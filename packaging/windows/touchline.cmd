@echo off
rem Touchline on Windows: the console and the headless commands from the jars in lib\ (built by
rem `./touchline package --platform win` on Linux, with the Windows JavaFX jars). Needs Java 17 or
rem newer: java on the PATH, or JAVA_HOME set. UDP runs on NIO and the GameController sender at
rem normal priority (the portable fallbacks; the window's status bar says so).
rem   touchline.cmd console          the window
rem   touchline.cmd listen           print the robots seen
rem   touchline.cmd --version
setlocal
set "HERE=%~dp0"
set "JAVA=java"
if defined JAVA_HOME set "JAVA=%JAVA_HOME%\bin\java"
"%JAVA%" -version >nul 2>&1
if errorlevel 1 (
  echo Touchline needs Java 17 or newer: install it ^(e.g. Eclipse Temurin 17^) or set JAVA_HOME. 1>&2
  exit /b 1
)
set "ARGS=%*"
if "%ARGS%"=="" set "ARGS=console"
"%JAVA%" -XX:+UseZGC %TOUCHLINE_JAVA_OPTS% -cp "%HERE%lib\*" touchline.cli.Main %ARGS%
exit /b %errorlevel%
