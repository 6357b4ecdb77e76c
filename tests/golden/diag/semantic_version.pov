#version 3.8;
